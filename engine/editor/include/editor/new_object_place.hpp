// Where a new shape goes: in front of the camera, not at the origin inside whatever is there.
// Resting on the surface under the view's centre when the ray through it meets one (an SDF
// surface or a mesh, as a click there would pick it), else at a distance along the view; and
// the node's position in its parent group that puts it there. GL-free.
#pragma once

#include "editor/picking.hpp"
#include "prepare/prepared_scene.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace rmsc::editor {

// Where a new object goes: the world point, and the unit normal of the surface there (facing
// the ray's origin), zero when the ray met no surface.
struct NewObjectSpot {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f};
};

// Where `ray` first meets a surface of `prepared` (nullptr: no scene has compiled yet), with the
// surface's normal there (from the hits of two rays beside it); else `fallbackDistance` along
// it (clamped to the ray's [tMin, tMax]).
NewObjectSpot newObjectSpot(const PreparedScene* prepared, const PickRay& ray,
                            float fallbackDistance);

// Sets the position of the SDF node at `path` so that its origin is at world point `world`
// (its parent groups' transforms undone); false when there is no such node.
bool placeSdfNodeAt(Scene& scene, const std::vector<int>& path, glm::vec3 world);
// The same at `spot`, resting on its surface: the origin moved out along the normal by as far
// as the node's box reaches against it (in the world, through its parent groups), so a new
// sphere sits on the floor instead of half inside it. An unbounded node goes at the point.
bool placeSdfNodeOn(Scene& scene, const std::vector<int>& path, const NewObjectSpot& spot);

} // namespace rmsc::editor
