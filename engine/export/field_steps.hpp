// The SDF's gradient by finite differences and Newton steps onto its surface: what dual
// contouring (its edge crossings' normals, its vertices) and the adaptive octree (the vertex of
// a collapsed cluster) share. Internal to rmsc_export.
#pragma once

#include "export/dual_contouring.hpp"

#include <glm/glm.hpp>

#include <cstdint>

namespace rmsc::exporter {

// The gradient by the tetrahedron technique (4 evaluations; Quilez, "normals for an SDF"):
// sum k_i f(p + h k_i) = 4 h grad f + O(h^3).
glm::vec3 rawGradient(const SdfField& field, glm::vec3 p, float h, std::int64_t& evaluations);
// rawGradient made unit length ((0, 1, 0) where it vanishes).
glm::vec3 unitGradient(const SdfField& field, glm::vec3 p, float h, std::int64_t& evaluations);

// Up to four Newton steps from p onto d = 0 along the gradient, x -= d grad d / |grad d|^2
// (which also holds where step corrections make the field's slope less than 1), each kept in
// the box [lo, hi]; stops within `tolerance` of the surface.
glm::vec3 stepOntoSurface(const SdfField& field, glm::vec3 p, glm::vec3 lo, glm::vec3 hi,
                          float gradientStep, float tolerance, std::int64_t& evaluations);

} // namespace rmsc::exporter
