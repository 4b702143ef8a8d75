// Where a new shape goes: in front of the camera, not at the origin inside whatever is there.
// On the surface under the view's centre when the ray through it meets one (an SDF surface or
// a mesh, as a click there would pick it), else at a distance along the view; and the node's
// position in its parent group that puts its origin at that world point. GL-free.
#pragma once

#include "editor/picking.hpp"
#include "prepare/prepared_scene.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace rmsc::editor {

// The world point a new object is put at: where `ray` first meets a surface of `prepared`
// (nullptr: no scene has compiled yet), else `fallbackDistance` along it (clamped to the ray's
// [tMin, tMax]).
glm::vec3 newObjectPoint(const PreparedScene* prepared, const PickRay& ray, float fallbackDistance);

// Sets the position of the SDF node at `path` so that its origin is at world point `world`
// (its parent groups' transforms undone); false when there is no such node.
bool placeSdfNodeAt(Scene& scene, const std::vector<int>& path, glm::vec3 world);

} // namespace rmsc::editor
