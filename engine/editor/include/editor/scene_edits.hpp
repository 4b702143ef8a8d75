// Structural edits of a Scene used by the editor: finding SDF nodes by path, adding, deleting,
// duplicating, moving and reordering nodes, meshes and lights, mapping object ids (the id AOV) back
// to what they show, and rough bounds for framing. GL-free; every function keeps the scene valid to
// compile (no empty groups are left behind).
#pragma once

#include "editor/selection.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace rmsc::editor {

// The node at `path`, or nullptr when the path does not exist.
SdfNode* findSdfNode(Scene& scene, const std::vector<int>& path);
const SdfNode* findSdfNode(const Scene& scene, const std::vector<int>& path);
// True when the selection names something that exists in `scene`.
bool selectionValid(const Scene& scene, const Selection& selection);

// World matrix of the node at `path` (product of the transforms from the root), and of its
// parent (identity for the root).
glm::mat4 sdfWorldMatrix(const Scene& scene, const std::vector<int>& path);
glm::mat4 sdfParentWorldMatrix(const Scene& scene, const std::vector<int>& path);

// A new shape with the catalogue's default parameters, named after the primitive.
SdfNode makeShape(PrimitiveId primitive);
// A group of `op` holding one default sphere (an empty group would not compile).
SdfNode makeGroup(SdfOp op);

// Inserts `node` next to the selection: into the selected group (last child), after a selected
// shape in its parent group, or at the end of the root group. A scene without an SDF gets
// `node` as root; a root that is a shape is first wrapped in a union group. Returns the new
// node's path.
std::vector<int> insertSdfNode(Scene& scene, const Selection& near, SdfNode node);

// Removes the node at `path`; a group left empty is removed too, the root leaves no SDF.
// Returns false when the path does not exist.
bool deleteSdfNode(Scene& scene, const std::vector<int>& path);
// Copies the node at `path` right after itself ("name copy"); returns the copy's path.
std::optional<std::vector<int>> duplicateSdfNode(Scene& scene, const std::vector<int>& path);

// Moves the node at `from` into group `intoGroup` at child position `index` (-1 = last).
// Refuses (returns nullopt) moving the root, moving a node into itself or its own subtree,
// or a target that is not a group. Returns the node's new path.
std::optional<std::vector<int>> moveSdfNode(Scene& scene, const std::vector<int>& from,
                                            const std::vector<int>& intoGroup, int index);

// Meshes and lights.
int addMesh(Scene& scene, const std::filesystem::path& file); // index of the new instance
// Appends editor/light_edits.hpp's makeLight(type, position); returns its index, or -1 (nothing
// added) when the scene already has limits::kLights lights.
int addLight(Scene& scene, LightType type = LightType::Directional,
             glm::vec3 position = Light{}.position);
bool deleteMesh(Scene& scene, int index);
bool deleteLight(Scene& scene, int index);
int duplicateMesh(Scene& scene, int index);
// The copy's index, or -1 (nothing added) when the scene already has limits::kLights lights.
int duplicateLight(Scene& scene, int index);
// Moves mesh instance / light `from` to position `to` in its list (the others keep their order;
// moving down puts it after the one that was at `to`). Returns the new index, or -1 (nothing
// changed) when either index is out of range.
int moveMesh(Scene& scene, int from, int to);
int moveLight(Scene& scene, int from, int to);

// Deletes / duplicates whatever is selected; returns the selection afterwards (unchanged, and
// the scene too, when a light is to be duplicated in a scene of limits::kLights lights).
Selection deleteSelected(Scene& scene, const Selection& selection);
Selection duplicateSelected(Scene& scene, const Selection& selection);

// What an object id of the id AOV shows (kMeshIdBase + mesh index, kSdfIdBase + pre-order
// index of the SDF node), or none for the background / an unknown id.
Selection selectionForObjectId(const Scene& scene, std::uint32_t objectId);
// The id range [first, last) drawn by the selection: a group covers its whole subtree.
struct IdRange {
    std::uint32_t first = 0;
    std::uint32_t last = 0;
    bool operator==(const IdRange&) const = default;
};
IdRange objectIdRange(const Scene& scene, const Selection& selection);
// Every object has the same id in both scenes (the same meshes and the same SDF tree shape): an
// id buffer drawn from one shows the other's selection where it is. False after a structural
// edit (a node added, deleted, moved to another group), which renumbers what follows.
bool sameObjectIds(const Scene& a, const Scene& b);

// A sphere around the selected object in world space (rough: from the parameters' sizes and
// the transform scales; a light's marker for lights), for framing and orbiting.
struct Bounds {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};
std::optional<Bounds> selectionBounds(const Scene& scene, const Selection& selection);

// A name for display: the node's name, or its shape (a profile solid's "extrusion",
// "revolution") / operation.
std::string displayName(const SdfNode& node);

} // namespace rmsc::editor
