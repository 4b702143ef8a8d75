// Ray / segment approach (see ray_segment.hpp).
#include "editor/ray_segment.hpp"

#include <algorithm>

namespace rmsc::editor {

std::optional<SegmentApproach> raySegmentApproach(glm::vec3 origin, glm::vec3 direction,
                                                  glm::vec3 a, glm::vec3 b, float tMin,
                                                  float tMax) {
    // Across the ray (the components along it removed), the segment runs from wa to wa + e; its
    // point nearest the ray's line minimises |wa + s e| for s in [0, 1].
    const glm::vec3 toA = a - origin, edge = b - a;
    const glm::vec3 wa = toA - direction * glm::dot(toA, direction);
    const glm::vec3 e = edge - direction * glm::dot(edge, direction);
    const float ee = glm::dot(e, e);
    const float s = ee > 1e-20f ? std::clamp(-glm::dot(wa, e) / ee, 0.0f, 1.0f) : 0.0f;
    const glm::vec3 q = a + s * edge;
    const float t = glm::dot(q - origin, direction);
    if (!(t >= tMin && t <= tMax)) return std::nullopt;
    return SegmentApproach{t, s, glm::length(wa + s * e)};
}

} // namespace rmsc::editor
