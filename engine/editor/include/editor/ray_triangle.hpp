// Ray / triangle and ray / box intersection for picking meshes on the CPU (editor/picking.hpp).
// Plain functions on GLM vectors; GL-free.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace rmsc::editor {

// Distance t along `direction` (not necessarily normalized: the hit is origin + t * direction)
// where the ray meets triangle (a, b, c), from either side, or nullopt when it misses or the
// hit lies outside [tMin, tMax]. Möller and Trumbore, "Fast, Minimum Storage Ray/Triangle
// Intersection", Journal of Graphics Tools 2(1), 1997.
std::optional<float> rayTriangle(glm::vec3 origin, glm::vec3 direction, glm::vec3 a, glm::vec3 b,
                                 glm::vec3 c, float tMin, float tMax);

// A ray's hit on a triangle: the distance t, the barycentric weights u (of b) and v (of c),
// and whether it meets the front face (a, b, c counter-clockwise as seen from the origin).
struct TriangleHit {
    float t = 0.0f;
    float u = 0.0f;
    float v = 0.0f;
    bool frontFace = true;
};

// rayTriangle with the hit's barycentric weights and side.
std::optional<TriangleHit> rayTriangleHit(glm::vec3 origin, glm::vec3 direction, glm::vec3 a,
                                          glm::vec3 b, glm::vec3 c, float tMin, float tMax);

// True when the ray meets the axis-aligned box [boxMin, boxMax] somewhere in [tMin, tMax]
// (the slab method: Kay and Kajiya, "Ray Tracing Complex Scenes", SIGGRAPH 1986).
bool rayHitsBox(glm::vec3 origin, glm::vec3 direction, glm::vec3 boxMin, glm::vec3 boxMax,
                float tMin, float tMax);

} // namespace rmsc::editor
