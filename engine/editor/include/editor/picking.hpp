// Picking by CPU ray casts: which object a ray from the camera meets first. SDF objects are
// sphere-traced by the CPU evaluator (sdf/cpu_eval.hpp) on the compiled program and named by
// the object id of the surface they hit; mesh instances are tested triangle by triangle
// (editor/ray_triangle.hpp) against the geometry the scene preparation loaded, and their lines
// and points where the ray passes within kLinePickPixels pixels of them (editor/ray_segment.hpp).
// The nearest hit wins, as in the rendered image. GL-free: works on a PreparedScene, so it can be
// tested without a window.
#pragma once

#include "editor/selection.hpp"
#include "prepare/prepared_scene.hpp"

#include <cstdint>
#include <optional>

namespace rmsc::editor {

// A ray in world space: origin + t * direction, direction of unit length, looking for hits
// with t in [tMin, tMax] (for a camera ray: the near and far planes along this ray). The size
// of a pixel at distance t is pixelSize + pixelSpread * t (a perspective camera's pixel grows
// with t, an orthographic one's does not); with both 0, lines and points are never hit.
struct PickRay {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float tMin = 0.0f;
    float tMax = 1e30f;
    float pixelSize = 0.0f;
    float pixelSpread = 0.0f;
};

// How near a ray must pass a glTF line or point to pick it, in pixels (lines are drawn one
// pixel wide and points kGltfPointSize pixels, render/raster_pass.hpp).
constexpr float kLinePickPixels = 2.0f;

// What a ray hit: the object id the id AOV would show there (kMeshIdBase + mesh index,
// kSdfIdBase + SDF node pre-order index), the distance along the ray, and the selection it maps
// to in the prepared scene.
struct PickHit {
    std::uint32_t objectId = 0;
    float t = 0.0f;
    Selection selection;
};

// The nearest mesh triangle, line or point along the ray over every mesh instance (placed by
// its transform).
std::optional<PickHit> pickMesh(const PreparedScene& prepared, const PickRay& ray);
// The SDF surface along the ray (sphere tracing with the scene's render settings; rays also
// stop at render.maxDistance, as in the march pass).
std::optional<PickHit> pickSdf(const PreparedScene& prepared, const PickRay& ray);
// The nearer of the two, or nullopt when the ray meets nothing.
std::optional<PickHit> pick(const PreparedScene& prepared, const PickRay& ray);

} // namespace rmsc::editor
