// Distance estimators of the fractal primitives, each behind a bounding sphere: outside it the
// distance to the sphere is returned (a lower bound, since the fractal lies inside), so a fractal
// costs one length() far away. Integer parameters (iterations) arrive as floats and are floored.
// Each mirrors the GLSL function of the same name in shaders/common/sdf_primitives.glsl.
#include "primitive_formulas.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::formulas {
namespace {

using glm::vec3;
using glm::vec4;

// Bounding-sphere test shared by the fractals: the distance to the sphere of `radius` when p is
// more than `margin` outside it, else a negative value (evaluate the fractal).
float outsideBound(vec3 p, float radius, float margin) {
    const float r = glm::length(p);
    return r > radius + margin ? r - radius : -1.0f;
}

} // namespace

// Mandelbulb (White and Nylander's triplex power, y as the polar axis) with the distance
// estimate 0.5 |z| log|z| / |z'| tracked through the running derivative dr = n r^(n-1) dr + 1:
// Inigo Quilez, "Mandelbulb" (https://iquilezles.org/articles/mandelbulb/), after Hubbard and
// Douady's potential-based estimate. Bound: |z^n + c| >= |z|^n - |c| gives escape for
// |c| > 2^(1/(n-1)), so the set (at any iteration count) lies in that ball.
float mandelbulb(vec3 p, const float* a) {
    const float n = a[0];
    const int iterations = int(std::floor(a[1]));
    const float bailout = a[2];
    const float bound = std::pow(2.0f, 1.0f / (n - 1.0f));
    const float outside = outsideBound(p, bound, 0.1f);
    if (outside >= 0.0f) return outside;
    vec3 z = p;
    float dr = 1.0f;
    float r = std::max(glm::length(z), 1e-10f);
    for (int i = 0; i < iterations && r <= bailout; ++i) {
        const float theta = std::acos(std::clamp(z.y / r, -1.0f, 1.0f)) * n;
        const float phi = std::atan2(z.x, z.z) * n;
        dr = std::pow(r, n - 1.0f) * n * dr + 1.0f;
        const float zr = std::pow(r, n);
        z = zr * vec3(std::sin(theta) * std::sin(phi), std::cos(theta),
                      std::sin(theta) * std::cos(phi)) +
            p;
        r = std::max(glm::length(z), 1e-10f);
    }
    return 0.5f * std::log(r) * r / dr;
}

// Menger sponge: the box [-1, 1]^3 intersected with the complement of the crosses of every
// level, each cross measured in the repeated cell: Inigo Quilez, "Menger fractal"
// (https://iquilezles.org/articles/menger/), the classic IFS construction evaluated
// iteratively. Bound: the circumscribed sphere of the box.
float mengerSponge(vec3 p, const float* a) {
    const int iterations = int(std::floor(a[0]));
    const float size = a[1]; // half the edge
    const float outside = outsideBound(p, size * 1.7320508f, 0.1f * size);
    if (outside >= 0.0f) return outside;
    p /= size;
    const vec3 b = glm::abs(p) - 1.0f;
    float d = glm::length(glm::max(b, 0.0f)) + std::min(std::max(b.x, std::max(b.y, b.z)), 0.0f);
    float s = 1.0f;
    for (int m = 0; m < iterations; ++m) {
        const vec3 ps = p * s;
        const vec3 cell = ps - 2.0f * glm::floor(ps / 2.0f) - 1.0f; // GLSL mod(ps, 2) - 1
        s *= 3.0f;
        const vec3 r = glm::abs(1.0f - 3.0f * glm::abs(cell));
        const float da = std::max(r.x, r.y);
        const float db = std::max(r.y, r.z);
        const float dc = std::max(r.z, r.x);
        const float c = (std::min(da, std::min(db, dc)) - 1.0f) / s;
        d = std::max(d, c);
    }
    return d * size;
}

// Sierpinski tetrahedron by folding space (reflections across the planes x + y = 0,
// x + z = 0, y + z = 0 bring p next to the vertex (1, 1, 1)), then scaling by 2 about that
// vertex; the distance to the tetrahedron of that level, divided by 2^iterations:
// M. Hvidtfeldt Christensen, "Distance Estimated 3D Fractals (III): Folding Space" (2011).
// Bound: the circumscribed sphere of the tetrahedron with vertices (+-1, +-1, +-1) * size.
float sierpinskiTetrahedron(vec3 p, const float* a) {
    const int iterations = int(std::floor(a[0]));
    const float size = a[1];
    const float outside = outsideBound(p, size * 1.7320508f, 0.1f * size);
    if (outside >= 0.0f) return outside;
    vec3 z = p / size;
    for (int i = 0; i < iterations; ++i) {
        if (z.x + z.y < 0.0f) z = vec3(-z.y, -z.x, z.z);
        if (z.x + z.z < 0.0f) z = vec3(-z.z, z.y, -z.x);
        if (z.y + z.z < 0.0f) z = vec3(z.x, -z.z, -z.y);
        z = z * 2.0f - 1.0f;
    }
    const float planes = std::max(std::max(-z.x - z.y - z.z, z.x + z.y - z.z),
                                  std::max(-z.x + z.y + z.z, z.x - z.y + z.z));
    return (planes - 1.0f) * 0.57735027f * std::exp2(-float(iterations)) * size;
}

// Quaternion Julia set z -> z^2 + c, sliced at the fourth component 0 (z = (x, y, z, 0), the
// first component real), with the distance estimate |z| log|z| / (2 |z'|) and |z'| tracked as
// |z'| -> 2 |z| |z'|: Hart, Sandin and Kauffman, "Ray tracing deterministic 3-D fractals"
// (SIGGRAPH 1989). Bound: once |z| > (1 + sqrt(1 + 4 |c|)) / 2, |z^2 + c| >= |z|^2 - |c| > |z|
// and z escapes, so the set lies in that ball.
float quaternionJulia(vec3 p, const float* a) {
    const vec4 c(a[0], a[1], a[2], a[3]);
    const int iterations = int(std::floor(a[4]));
    const float bound = 0.5f * (1.0f + std::sqrt(1.0f + 4.0f * glm::length(c)));
    const float outside = outsideBound(p, bound, 0.1f);
    if (outside >= 0.0f) return outside;
    vec4 z(p, 0.0f);
    float dz = 1.0f;
    float m2 = glm::dot(z, z);
    for (int i = 0; i < iterations && m2 <= 256.0f; ++i) {
        dz = 2.0f * std::sqrt(m2) * dz;
        const vec3 v(z.y, z.z, z.w);
        z = vec4(z.x * z.x - glm::dot(v, v), 2.0f * z.x * v) + c;
        m2 = glm::dot(z, z);
    }
    const float m = std::max(std::sqrt(m2), 1e-10f);
    return 0.5f * m * std::log(m) / std::max(dz, 1e-10f);
}

} // namespace rmsc::formulas
