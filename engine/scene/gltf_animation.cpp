// Sampling a glTF animation sampler at a time (see gltf_animation.hpp).
#include "scene/gltf_animation.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {

namespace {

// The value of key `key` (CUBICSPLINE: its middle group, after the in-tangent).
const float* keyValue(const AnimationSampler& s, std::size_t key) {
    const std::size_t w = std::size_t(s.width);
    return s.interpolation == AnimationInterpolation::CubicSpline ? &s.values[(3 * key + 1) * w]
                                                                  : &s.values[key * w];
}

void normaliseQuaternion(float* q) {
    const double length = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] +
                                    double(q[2]) * q[2] + double(q[3]) * q[3]);
    if (!(length > 1e-12)) {
        q[0] = q[1] = q[2] = 0.0f;
        q[3] = 1.0f;
        return;
    }
    for (int i = 0; i < 4; ++i)
        q[i] = float(q[i] / length);
}

// Spherical linear interpolation of unit quaternions a and b at t in [0, 1], along the shorter
// arc (glTF 2.0 Appendix C, "Spherical Linear Interpolation"): sin((1-t) w) / sin(w) a +
// sin(t w) / sin(w) b with cos(w) = a . b, b negated when a . b < 0.
void slerp(const float* a, const float* b, double t, float* out) {
    double d = 0.0;
    for (int i = 0; i < 4; ++i)
        d += double(a[i]) * b[i];
    const double sign = d < 0.0 ? -1.0 : 1.0;
    d = std::abs(d);
    double wa = 1.0 - t, wb = t;
    if (d < 1.0 - 1e-9) { // nearly equal quaternions: linear, then normalised below
        const double angle = std::acos(std::min(d, 1.0));
        const double s = std::sin(angle);
        wa = std::sin((1.0 - t) * angle) / s;
        wb = std::sin(t * angle) / s;
    }
    for (int i = 0; i < 4; ++i)
        out[i] = float(wa * a[i] + wb * sign * b[i]);
    normaliseQuaternion(out);
}

} // namespace

void sampleAnimation(const AnimationSampler& s, double time, bool rotation, float* out) {
    const std::size_t w = std::size_t(s.width);
    const std::size_t keys = s.times.size();
    if (keys == 0 || w == 0) return;
    const auto copy = [&](const float* value) { std::copy(value, value + w, out); };
    if (!(time > double(s.times.front()))) { // before the first key (and NaN)
        copy(keyValue(s, 0));
        return;
    }
    if (time >= double(s.times.back())) {
        copy(keyValue(s, keys - 1));
        return;
    }
    // The key interval [t_k, t_k+1) holding the time.
    const std::size_t k =
        std::size_t(std::upper_bound(s.times.begin(), s.times.end(), float(time)) -
                    s.times.begin()) -
        1;
    const std::size_t next = std::min(k + 1, keys - 1);
    const double t0 = s.times[k], t1 = s.times[next];
    const double span = t1 - t0;
    const double t = span > 0.0 ? std::clamp((time - t0) / span, 0.0, 1.0) : 0.0;
    switch (s.interpolation) {
    case AnimationInterpolation::Step:
        copy(keyValue(s, k));
        return;
    case AnimationInterpolation::Linear:
        if (rotation) {
            slerp(keyValue(s, k), keyValue(s, next), t, out);
        } else {
            const float* a = keyValue(s, k);
            const float* b = keyValue(s, next);
            for (std::size_t i = 0; i < w; ++i)
                out[i] = float((1.0 - t) * a[i] + t * b[i]);
        }
        return;
    case AnimationInterpolation::CubicSpline: {
        // glTF 2.0 Appendix C, "Cubic Spline Interpolation": with t_d = t_k+1 - t_k,
        // p(t) = (2t^3 - 3t^2 + 1) v_k + t_d (t^3 - 2t^2 + t) b_k + (-2t^3 + 3t^2) v_k+1
        //        + t_d (t^3 - t^2) a_k+1,
        // v the values, b_k the out-tangent of key k and a_k+1 the in-tangent of key k+1.
        const double t2 = t * t, t3 = t2 * t;
        const double hv0 = 2 * t3 - 3 * t2 + 1, hb0 = span * (t3 - 2 * t2 + t);
        const double hv1 = -2 * t3 + 3 * t2, ha1 = span * (t3 - t2);
        const float* v0 = &s.values[(3 * k + 1) * w];
        const float* b0 = &s.values[(3 * k + 2) * w];
        const float* a1 = &s.values[(3 * next) * w];
        const float* v1 = &s.values[(3 * next + 1) * w];
        for (std::size_t i = 0; i < w; ++i)
            out[i] = float(hv0 * v0[i] + hb0 * b0[i] + hv1 * v1[i] + ha1 * a1[i]);
        if (rotation) normaliseQuaternion(out);
        return;
    }
    }
}

} // namespace rmsc
