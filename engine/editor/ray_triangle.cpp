// Ray / triangle and ray / box intersection (see ray_triangle.hpp).
#include "editor/ray_triangle.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

std::optional<TriangleHit> rayTriangleHit(glm::vec3 origin, glm::vec3 direction, glm::vec3 a,
                                          glm::vec3 b, glm::vec3 c, float tMin, float tMax) {
    // Möller–Trumbore: solve origin + t * direction = a + u * (b - a) + v * (c - a) by Cramer's
    // rule, with the determinants written as scalar triple products.
    const glm::vec3 edge1 = b - a;
    const glm::vec3 edge2 = c - a;
    const glm::vec3 p = glm::cross(direction, edge2);
    const float determinant = glm::dot(edge1, p);
    // Parallel to the triangle's plane (or a degenerate triangle); relative to the edge sizes
    // so tiny and huge meshes behave alike.
    const float scale = glm::length(edge1) * glm::length(p);
    if (!(std::abs(determinant) > 1e-12f * scale)) return std::nullopt;
    const float inverse = 1.0f / determinant;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const glm::vec3 q = glm::cross(s, edge1);
    const float v = glm::dot(direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    const float t = glm::dot(edge2, q) * inverse;
    if (t < tMin || t > tMax) return std::nullopt;
    // determinant = -dot(direction, cross(edge1, edge2)): positive when the ray meets the side
    // from which a, b, c run counter-clockwise.
    return TriangleHit{t, u, v, determinant > 0.0f};
}

std::optional<float> rayTriangle(glm::vec3 origin, glm::vec3 direction, glm::vec3 a, glm::vec3 b,
                                 glm::vec3 c, float tMin, float tMax) {
    const std::optional<TriangleHit> hit = rayTriangleHit(origin, direction, a, b, c, tMin, tMax);
    if (!hit) return std::nullopt;
    return hit->t;
}

bool rayHitsBox(glm::vec3 origin, glm::vec3 direction, glm::vec3 boxMin, glm::vec3 boxMax,
                float tMin, float tMax) {
    // Intersect the ray's [tMin, tMax] with the interval inside each pair of parallel planes.
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-30f) {
            if (origin[axis] < boxMin[axis] || origin[axis] > boxMax[axis]) return false;
            continue;
        }
        const float inverse = 1.0f / direction[axis];
        float t0 = (boxMin[axis] - origin[axis]) * inverse;
        float t1 = (boxMax[axis] - origin[axis]) * inverse;
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

} // namespace rmsc::editor
