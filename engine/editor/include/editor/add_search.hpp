// The searchable add menu's model (Shift+A in the view): every thing the editor can add,
// generated from the catalogues (each primitive, each profile solid, a group of each operation,
// each light type, a glTF mesh), and the search over them that the menu's field runs: each word
// typed must occur in an item's name or category (those come first) or its description, without
// regard to case, and "_" matches a space. GL-free.
#pragma once

#include "scene/scene.hpp"
#include "sdf/primitives.hpp"
#include "sdf/sdf_tree.hpp"

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rmsc::editor {

enum class AddCategory { Shape, ProfileShape, Group, Light, Mesh };

struct AddMeshFromFile {}; // asks for the glTF file

struct AddItem {
    AddCategory category;
    std::string name;             // the catalogue's JSON name ("round_box"), or the item's
    std::string_view description; // the catalogue's
    std::variant<PrimitiveId, SdfProfileSolid, SdfOp, LightType, AddMeshFromFile> what;
};

std::string_view addCategoryName(AddCategory category); // "Shape", "Profile shape", ...

// Every item, in menu order: the primitives, the profile solids, the groups, the lights, the
// mesh.
const std::vector<AddItem>& addItems();

// Indices into `items` that match `query`, best first: items whose name or category hold every
// word, in menu order, then those that need their description. An empty query matches all.
std::vector<int> searchAddItems(const std::vector<AddItem>& items, std::string_view query);

// The highlighted row after moving it by `delta` rows among `count`, stopping at either end;
// -1 when there are none.
int moveHighlight(int highlighted, int delta, int count);

} // namespace rmsc::editor
