// Fitting shadow-map frusta to the casters' bounds.
#include "render/shadow_views.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace rmsc {
namespace {

// An up vector not parallel to `forward`.
glm::vec3 upFor(const glm::vec3& forward) {
    return std::abs(forward.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

std::array<glm::vec3, 8> corners(const CasterBounds& b) {
    std::array<glm::vec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[std::size_t(i)] = {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                             i & 4 ? b.max.z : b.min.z};
    return c;
}

// Orthographic view along `direction` whose square window holds every caster corner; depth
// covers the casters (receivers beyond the far plane are compared as if at it).
GpuShadowView directionalView(const glm::vec3& direction, const CasterBounds& casters,
                              int mapSize) {
    const glm::vec3 centre = 0.5f * (casters.min + casters.max);
    const float radius = std::max(0.5f * glm::length(casters.max - casters.min), 1e-3f);
    const glm::vec3 forward = glm::normalize(direction);
    const glm::mat4 view = glm::lookAt(centre - forward * (2.0f * radius), centre, upFor(forward));
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& corner : corners(casters)) {
        const glm::vec3 v = glm::vec3(view * glm::vec4(corner, 1.0f));
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    // A square window (one texel size for both axes), with a margin of a few texels for PCF.
    float half = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y);
    half *= 1.0f + 8.0f / float(mapSize);
    half = std::max(half, 1e-3f);
    const glm::vec2 middle = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
    // View space looks down -z: near = -hi.z, far = -lo.z.
    const float nearPlane = -hi.z - 0.01f * radius;
    const float farPlane = -lo.z + 0.01f * radius;
    const glm::mat4 projection = glm::ortho(middle.x - half, middle.x + half, middle.y - half,
                                            middle.y + half, nearPlane, farPlane);
    GpuShadowView out{};
    out.lightViewProjection = projection * view;
    out.params = glm::vec4(2.0f * half / float(mapSize), 0.0f, 0.0f, 0.0f);
    return out;
}

// The farthest caster corner from `position` (at least a little beyond the near plane).
float farthestCaster(const glm::vec3& position, const CasterBounds& casters) {
    float farthest = 0.0f;
    for (const glm::vec3& corner : corners(casters))
        farthest = std::max(farthest, glm::length(corner - position));
    return std::max(farthest * 1.01f, 0.2f);
}

GpuShadowView perspectiveView(const glm::vec3& position, const glm::vec3& forward,
                              const glm::vec3& up, float fovDegrees, float farPlane, int mapSize) {
    const float nearPlane = std::max(farPlane * 1e-3f, 0.02f);
    const float fov = glm::radians(fovDegrees);
    const glm::mat4 view = glm::lookAt(position, position + forward, up);
    const glm::mat4 projection = glm::perspective(fov, 1.0f, nearPlane, farPlane);
    GpuShadowView out{};
    out.lightViewProjection = projection * view;
    out.params = glm::vec4(2.0f * std::tan(0.5f * fov) / float(mapSize), 1.0f, 0.0f, 0.0f);
    return out;
}

} // namespace

void CasterBounds::add(const glm::vec3& point) {
    min = empty ? point : glm::min(min, point);
    max = empty ? point : glm::max(max, point);
    empty = false;
}

ShadowViewPlan planShadowViews(const std::vector<Light>& lights, const CasterBounds& casters,
                               const ShadowSettings& settings) {
    ShadowViewPlan plan;
    plan.firstView.assign(lights.size(), -1);
    if (!settings.enabled || casters.empty) return plan;
    const int mapSize = std::clamp(settings.mapSize, 1, 4096);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        if (!light.castShadows || light.intensity <= 0.0f) continue;
        const int needed = light.type == LightType::Point ? 6 : 1;
        if (int(plan.views.size()) + needed > kMaxShadowViews) continue;
        plan.firstView[i] = int(plan.views.size());
        if (light.type == LightType::Directional) {
            plan.views.push_back(directionalView(light.direction, casters, mapSize));
        } else if (light.type == LightType::Spot) {
            const glm::vec3 forward = glm::normalize(light.direction);
            // The cone plus a margin for PCF; wide cones are capped (outside counts as lit).
            const float fov = std::min(2.0f * light.outerAngleDegrees + 4.0f, 160.0f);
            plan.views.push_back(perspectiveView(light.position, forward, upFor(forward), fov,
                                                 farthestCaster(light.position, casters), mapSize));
        } else {
            const float farPlane = farthestCaster(light.position, casters);
            const glm::vec3 axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
            for (const glm::vec3& axis : axes)
                plan.views.push_back(
                    perspectiveView(light.position, axis, upFor(axis), 90.0f, farPlane, mapSize));
        }
    }
    for (std::size_t v = 0; v < plan.views.size(); ++v)
        plan.views[v].params.z = float(v);
    return plan;
}

} // namespace rmsc
