// Host cameras: everything the passes need, recovered from the two matrices.
#include "render/host_camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rmsc {
namespace {

bool near(float a, float b, float tolerance) {
    return std::abs(a - b) <= tolerance;
}

// The window depth (glDepthRange(0, 1)) of the eye-space point at view depth `z` on the axis.
float axisWindowDepth(const HostView& host, float z) {
    const glm::vec4 clip = host.projection * glm::vec4(0.0f, 0.0f, -z, 1.0f);
    const float ndc = clip.z / clip.w;
    return host.zeroToOne ? ndc : ndc * 0.5f + 0.5f;
}

// The view depth of the point on the axis at window depth `depth`; +infinity where the
// projection sends it to infinity (an infinite far plane).
float axisViewDepth(const glm::mat4& inverseProjection, const HostView& host, float depth) {
    const float ndc = host.zeroToOne ? depth : depth * 2.0f - 1.0f;
    const glm::vec4 eye = inverseProjection * glm::vec4(0.0f, 0.0f, ndc, 1.0f);
    if (std::abs(eye.w) < 1e-12f) return std::numeric_limits<float>::infinity();
    return -eye.z / eye.w;
}

} // namespace

std::optional<FrameCamera> hostFrameCamera(const HostView& host, std::string& error) {
    if (host.width <= 0 || host.height <= 0) {
        error = "the viewport is " + std::to_string(host.width) + "x" +
                std::to_string(host.height) + "; expected a positive size";
        return std::nullopt;
    }
    const glm::mat4& p = host.projection;
    // OpenGL perspective: the fourth row is (0, 0, -1, 0), so w = -z_eye (columns are p[i]).
    if (!near(p[0][3], 0.0f, 1e-6f) || !near(p[1][3], 0.0f, 1e-6f) ||
        !near(p[2][3], -1.0f, 1e-6f) || !near(p[3][3], 0.0f, 1e-6f)) {
        error = "the projection is not an OpenGL perspective projection (its last row must be "
                "0, 0, -1, 0: orthographic and other projections are not supported)";
        return std::nullopt;
    }
    const glm::mat3 rotation(host.view);
    const glm::mat3 gram = glm::transpose(rotation) * rotation;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!near(gram[i][j], i == j ? 1.0f : 0.0f, 1e-3f)) {
                error = "the view matrix is not a rotation and a translation (it scales or "
                        "shears; put scale into the objects' transforms instead)";
                return std::nullopt;
            }
    if (host.reversedZ && !host.zeroToOne) {
        error = "reversed-Z needs zero-to-one clip depth (glClipControl(GL_LOWER_LEFT, "
                "GL_ZERO_TO_ONE)); reversed-Z in OpenGL's default -1 to 1 clip space is not "
                "supported";
        return std::nullopt;
    }
    const glm::mat4 inverseProjection = glm::inverse(p);
    const float nearPlane = axisViewDepth(inverseProjection, host, host.reversedZ ? 1.0f : 0.0f);
    const float farPlane = axisViewDepth(inverseProjection, host, hostFarDepth(host));
    if (!(nearPlane > 0.0f) || !(farPlane > nearPlane)) {
        error = host.reversedZ
                    ? "the projection does not map the near plane to depth 1 and the far plane "
                      "to 0, as reversed-Z does (is it a reversed-Z projection?)"
                    : "the projection does not map the near plane to depth 0 and the far plane "
                      "to 1 (a reversed-Z projection needs reversed-Z set)";
        if (!host.zeroToOne && nearPlane > 0.0f) error += "; for clip depth 0 to 1 set zero-to-one";
        return std::nullopt;
    }
    // Depth must also grow the right way in between (it does for any projection whose planes
    // came out in order, but a wrong convention can still pass the test above).
    const float a = axisWindowDepth(host, nearPlane * 1.5f);
    const float b = axisWindowDepth(host, nearPlane * 3.0f);
    if (host.reversedZ ? !(a > b) : !(a < b)) {
        error = "the projection's depth does not run the way the depth convention says";
        return std::nullopt;
    }

    FrameCamera frame;
    frame.view = host.view;
    frame.projection = p;
    frame.viewProjection = p * host.view;
    const glm::mat4 eyeToWorld = glm::inverse(host.view);
    frame.position = glm::vec3(eyeToWorld[3]);
    frame.forward = glm::normalize(-glm::vec3(eyeToWorld[2]));
    // Corner rays: the eye-space points of the corners on the plane z = -1 (the ray through a
    // window position is affine in it, so the march pass's bilinear mix of these is exact).
    auto corner = [&](float x, float y) {
        const glm::vec4 onNear =
            inverseProjection * glm::vec4(x, y, host.zeroToOne ? 0.5f : 0.0f, 1.0f);
        const glm::vec3 eye = glm::vec3(onNear) / onNear.w;
        return glm::vec4(glm::mat3(eyeToWorld) * (eye / -eye.z), 0.0f);
    };
    frame.frustumCorners = glm::mat4(corner(-1, -1), corner(1, -1), corner(-1, 1), corner(1, 1));
    frame.nearPlane = nearPlane;
    frame.farPlane = std::min(farPlane, 1.0e30f); // an infinite projection: no far plane
    return frame;
}

} // namespace rmsc
