// Where the mesh shadow maps look from: one view per shadow-casting directional light (an
// orthographic frustum fitted to the bounds of the shadow casters), one per spot light (a
// perspective frustum covering the cone) and six per point light (90-degree cube faces, in the
// order +X, -X, +Y, -Y, +Z, -Z that shaders/common/shadows.glsl selects from). GL-free.
#pragma once

#include "core/limits.hpp"
#include "render/gpu_layout.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace rmsc {

// The most shadow-map layers a scene gets; lights past the budget cast no mesh shadows.
constexpr int kMaxShadowViews = limits::kShadowViews;

struct ShadowViewPlan {
    std::vector<GpuShadowView> views; // view i renders into layer i
    std::vector<int> firstView;       // per light: its first view, or -1
};

// Axis-aligned bounds of what casts mesh shadows (the mesh instances, world space).
struct CasterBounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    bool empty = true;

    void add(const glm::vec3& point);
};

// Plans the views of the shadow maps of `lights` (none when shadows are off or nothing casts).
ShadowViewPlan planShadowViews(const std::vector<Light>& lights, const CasterBounds& casters,
                               const ShadowSettings& settings);

} // namespace rmsc
