// Where a ray passes nearest a line segment (or a point: a segment of length zero), for picking
// glTF lines and points on the CPU (editor/picking.hpp). GL-free.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace rmsc::editor {

// The segment's point nearest the ray's line: s along the segment (0 at a, 1 at b), t along the
// ray (origin + t * direction, direction of unit length) where the ray comes closest to it, and
// the distance between the two.
struct SegmentApproach {
    float t = 0.0f;
    float s = 0.0f;
    float distance = 0.0f;
};

// The approach of segment (a, b) to the ray, or nullopt when it lies outside [tMin, tMax].
std::optional<SegmentApproach> raySegmentApproach(glm::vec3 origin, glm::vec3 direction,
                                                  glm::vec3 a, glm::vec3 b, float tMin, float tMax);

} // namespace rmsc::editor
