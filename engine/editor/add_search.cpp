// The searchable add menu's items and search (see editor/add_search.hpp).
#include "editor/add_search.hpp"

#include "scene/light_spec.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"

#include <algorithm>
#include <cctype>

namespace rmsc::editor {
namespace {

// Lower case, "_" as a space.
std::string folded(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text)
        out += c == '_' ? ' ' : char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::vector<std::string> words(std::string_view query) {
    std::vector<std::string> out;
    std::string word;
    for (char c : folded(query)) {
        if (c == ' ' || c == '\t') {
            if (!word.empty()) out.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    if (!word.empty()) out.push_back(word);
    return out;
}

bool holdsAll(const std::string& text, const std::vector<std::string>& wanted) {
    return std::all_of(wanted.begin(), wanted.end(),
                       [&](const std::string& w) { return text.find(w) != std::string::npos; });
}

std::vector<AddItem> makeItems() {
    std::vector<AddItem> items;
    for (const PrimitiveSpec& spec : primitiveCatalogue())
        items.push_back({AddCategory::Shape, std::string(spec.name), spec.description, spec.id});
    for (const ProfileSolidSpec& solid : profileSolidCatalogue())
        items.push_back(
            {AddCategory::ProfileShape, std::string(solid.name), solid.description, solid.solid});
    for (const OperationSpec& op : operationCatalogue())
        items.push_back({AddCategory::Group, std::string(op.name), op.description, op.op});
    for (const LightType type : kLightTypes)
        items.push_back({AddCategory::Light, std::string(lightTypeName(type)) + " light",
                         type == LightType::Directional ? "light from one direction (the sun)"
                         : type == LightType::Point     ? "light from a point, in every direction"
                                                        : "light from a point, in a cone",
                         type});
    items.push_back({AddCategory::Mesh, "glTF mesh from a file...",
                     "a .gltf or .glb model, as a mesh instance", AddMeshFromFile{}});
    return items;
}

} // namespace

std::string_view addCategoryName(AddCategory category) {
    switch (category) {
    case AddCategory::Shape:
        return "Shape";
    case AddCategory::ProfileShape:
        return "Profile shape";
    case AddCategory::Group:
        return "Group";
    case AddCategory::Light:
        return "Light";
    case AddCategory::Mesh:
        return "Mesh";
    }
    return "";
}

const std::vector<AddItem>& addItems() {
    static const std::vector<AddItem> items = makeItems();
    return items;
}

std::vector<int> searchAddItems(const std::vector<AddItem>& items, std::string_view query) {
    const std::vector<std::string> wanted = words(query);
    std::vector<int> byName, byDescription;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const AddItem& item = items[i];
        const std::string title = folded(item.name) + " " + folded(addCategoryName(item.category));
        if (holdsAll(title, wanted))
            byName.push_back(int(i));
        else if (holdsAll(title + " " + folded(item.description), wanted))
            byDescription.push_back(int(i));
    }
    byName.insert(byName.end(), byDescription.begin(), byDescription.end());
    return byName;
}

int moveHighlight(int highlighted, int delta, int count) {
    if (count <= 0) return -1;
    return std::clamp(highlighted + delta, 0, count - 1);
}

} // namespace rmsc::editor
