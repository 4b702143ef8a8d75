// The gradient and the Newton steps (see field_steps.hpp).
#include "field_steps.hpp"

namespace rmsc::exporter {

glm::vec3 rawGradient(const SdfField& field, glm::vec3 p, float h, std::int64_t& evaluations) {
    const glm::vec3 k0(1, -1, -1), k1(-1, -1, 1), k2(-1, 1, -1), k3(1, 1, 1);
    evaluations += 4;
    return (k0 * field.distance(p + h * k0) + k1 * field.distance(p + h * k1) +
            k2 * field.distance(p + h * k2) + k3 * field.distance(p + h * k3)) /
           (4.0f * h);
}

glm::vec3 unitGradient(const SdfField& field, glm::vec3 p, float h, std::int64_t& evaluations) {
    const glm::vec3 g = rawGradient(field, p, h, evaluations);
    const float length = glm::length(g);
    return length > 0.0f ? g / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

glm::vec3 stepOntoSurface(const SdfField& field, glm::vec3 p, glm::vec3 lo, glm::vec3 hi,
                          float gradientStep, float tolerance, std::int64_t& evaluations) {
    for (int it = 0; it < 4; ++it) {
        const float d = field.distance(p);
        ++evaluations;
        if (std::abs(d) < tolerance) break;
        const glm::vec3 g = rawGradient(field, p, gradientStep, evaluations);
        const float slope = glm::dot(g, g);
        if (!(slope > 1e-8f)) break;
        p = glm::clamp(p - d * g / slope, lo, hi);
    }
    return p;
}

} // namespace rmsc::exporter
