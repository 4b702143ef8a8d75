// Structural scene edits for the editor (see scene_edits.hpp).
#include "editor/scene_edits.hpp"

#include "core/limits.hpp"
#include "editor/light_edits.hpp"
#include "editor/profile_edits.hpp"
#include "sdf/operations.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace rmsc::editor {
namespace {

const SdfNode* findIn(const SdfNode& node, const std::vector<int>& path, std::size_t depth) {
    if (depth == path.size()) return &node;
    const int i = path[depth];
    if (!node.isGroup || i < 0 || i >= int(node.children.size())) return nullptr;
    return findIn(node.children[std::size_t(i)], path, depth + 1);
}

int subtreeSize(const SdfNode& node) {
    int n = 1;
    for (const SdfNode& child : node.children)
        n += subtreeSize(child);
    return n;
}

std::vector<int> parentPath(const std::vector<int>& path) {
    return {path.begin(), path.end() - 1};
}

bool isPrefix(const std::vector<int>& prefix, const std::vector<int>& path) {
    return prefix.size() <= path.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

float maxComponent(glm::vec3 v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Radius of a sphere around a node in its own space, from its parameters (shapes) or its
// children (groups). Infinite shapes (planes) count as size 1 so framing stays sensible.
float localRadius(const SdfNode& node) {
    if (!node.isGroup && node.profile)
        return std::clamp(profileSolidRadius(*node.profile), 0.05f, 10.0f);
    if (!node.isGroup) {
        const PrimitiveSpec& spec = primitiveSpec(node.primitive);
        float r = 0.0f;
        for (int i = 0; i < int(spec.params.size()); ++i) {
            const int offset = paramOffset(spec, i);
            for (int c = 0; c < spec.params[std::size_t(i)].components; ++c)
                r = std::max(r, std::abs(node.params[std::size_t(offset + c)]));
        }
        if (spec.params.size() > 1) r *= 1.5f; // e.g. a torus: major + minor radius
        return std::clamp(r, 0.05f, 10.0f);
    }
    float r = 0.05f;
    for (const SdfNode& child : node.children) {
        const float childR = localRadius(child) * maxComponent(child.transform.scale);
        r = std::max(r, glm::length(child.transform.position) + childR);
    }
    return r;
}

} // namespace

SdfNode* findSdfNode(Scene& scene, const std::vector<int>& path) {
    if (!scene.sdf) return nullptr;
    return const_cast<SdfNode*>(findIn(*scene.sdf, path, 0));
}

const SdfNode* findSdfNode(const Scene& scene, const std::vector<int>& path) {
    if (!scene.sdf) return nullptr;
    return findIn(*scene.sdf, path, 0);
}

bool selectionValid(const Scene& scene, const Selection& selection) {
    switch (selection.kind) {
    case SelectionKind::None:
        return true;
    case SelectionKind::Sdf:
        return findSdfNode(scene, selection.sdfPath) != nullptr;
    case SelectionKind::Mesh:
        return selection.index >= 0 && selection.index < int(scene.meshes.size());
    case SelectionKind::Light:
        return selection.index >= 0 && selection.index < int(scene.lights.size());
    }
    return false;
}

glm::mat4 sdfWorldMatrix(const Scene& scene, const std::vector<int>& path) {
    glm::mat4 m(1.0f);
    if (!scene.sdf) return m;
    const SdfNode* node = &*scene.sdf;
    m = node->transform.matrix();
    for (int i : path) {
        if (i < 0 || i >= int(node->children.size())) break;
        node = &node->children[std::size_t(i)];
        m = m * node->transform.matrix();
    }
    return m;
}

glm::mat4 sdfParentWorldMatrix(const Scene& scene, const std::vector<int>& path) {
    if (path.empty()) return glm::mat4(1.0f);
    return sdfWorldMatrix(scene, parentPath(path));
}

SdfNode makeShape(PrimitiveId primitive) {
    SdfNode node;
    const PrimitiveSpec& spec = primitiveSpec(primitive);
    node.name = std::string(spec.name);
    node.primitive = primitive;
    node.params = defaultParams(spec);
    return node;
}

SdfNode makeGroup(SdfOp op) {
    SdfNode group;
    group.name = "group";
    group.isGroup = true;
    group.op = op;
    group.children.push_back(makeShape(PrimitiveId::Sphere));
    if (operationSpec(op).combination == SdfOpCombination::Subtraction) {
        // A subtraction needs two children: a sphere minus a smaller, offset sphere.
        SdfNode cut = makeShape(PrimitiveId::Sphere);
        cut.transform.position = glm::vec3(0.5f, 0.3f, 0.3f);
        cut.transform.scale = glm::vec3(0.6f);
        group.children.push_back(cut);
    }
    if (takesSmoothness(op)) group.smoothness = 0.1f;
    return group;
}

std::vector<int> insertSdfNode(Scene& scene, const Selection& near, SdfNode node) {
    if (!scene.sdf) {
        SdfNode root;
        root.isGroup = true;
        root.op = SdfOp::Union;
        root.children.push_back(std::move(node));
        scene.sdf = std::move(root);
        return {0};
    }
    if (!scene.sdf->isGroup) {
        SdfNode root;
        root.isGroup = true;
        root.op = SdfOp::Union;
        root.children.push_back(std::move(*scene.sdf));
        scene.sdf = std::move(root);
        scene.sdf->children.push_back(std::move(node));
        return {1};
    }
    if (near.kind == SelectionKind::Sdf) {
        if (SdfNode* selected = findSdfNode(scene, near.sdfPath)) {
            if (selected->isGroup) {
                selected->children.push_back(std::move(node));
                std::vector<int> path = near.sdfPath;
                path.push_back(int(selected->children.size()) - 1);
                return path;
            }
            if (!near.sdfPath.empty()) {
                const std::vector<int> parent = parentPath(near.sdfPath);
                SdfNode* group = findSdfNode(scene, parent);
                const int at = near.sdfPath.back() + 1;
                group->children.insert(group->children.begin() + at, std::move(node));
                std::vector<int> path = parent;
                path.push_back(at);
                return path;
            }
        }
    }
    scene.sdf->children.push_back(std::move(node));
    return {int(scene.sdf->children.size()) - 1};
}

bool deleteSdfNode(Scene& scene, const std::vector<int>& path) {
    if (!findSdfNode(scene, path)) return false;
    std::vector<int> current = path;
    while (true) {
        if (current.empty()) {
            scene.sdf.reset();
            return true;
        }
        SdfNode* parent = findSdfNode(scene, parentPath(current));
        parent->children.erase(parent->children.begin() + current.back());
        if (!parent->children.empty()) return true;
        current = parentPath(current); // the group is now empty: remove it as well
    }
}

std::optional<std::vector<int>> duplicateSdfNode(Scene& scene, const std::vector<int>& path) {
    const SdfNode* node = findSdfNode(scene, path);
    if (!node || path.empty()) return std::nullopt; // the root has no sibling position
    SdfNode copy = *node;
    copy.name = displayName(*node) + " copy";
    SdfNode* parent = findSdfNode(scene, parentPath(path));
    parent->children.insert(parent->children.begin() + path.back() + 1, std::move(copy));
    std::vector<int> result = path;
    result.back() += 1;
    return result;
}

std::optional<std::vector<int>> moveSdfNode(Scene& scene, const std::vector<int>& from,
                                            const std::vector<int>& intoGroup, int index) {
    if (from.empty() || !findSdfNode(scene, from)) return std::nullopt;
    if (isPrefix(from, intoGroup)) return std::nullopt; // into itself or its own subtree
    const SdfNode* target = findSdfNode(scene, intoGroup);
    if (!target || !target->isGroup) return std::nullopt;
    const std::vector<int> fromParent = parentPath(from);
    if (fromParent == intoGroup && fromParent.size() + 0 == intoGroup.size()) {
        // Reorder within the same group.
        SdfNode* group = findSdfNode(scene, intoGroup);
        const int count = int(group->children.size());
        int to = index < 0 || index > count ? count : index;
        const int at = from.back();
        SdfNode moved = std::move(group->children[std::size_t(at)]);
        group->children.erase(group->children.begin() + at);
        if (to > at) --to;
        group->children.insert(group->children.begin() + to, std::move(moved));
        std::vector<int> result = intoGroup;
        result.push_back(to);
        return result;
    }
    if (findSdfNode(scene, fromParent)->children.size() == 1) return std::nullopt; // would empty it
    // Removing `from` shifts later siblings (and the target path if it runs through them).
    std::vector<int> target2 = intoGroup;
    if (target2.size() >= from.size() && isPrefix(fromParent, target2) &&
        target2[fromParent.size()] > from.back())
        target2[fromParent.size()] -= 1;
    SdfNode* parent = findSdfNode(scene, fromParent);
    SdfNode moved = std::move(parent->children[std::size_t(from.back())]);
    parent->children.erase(parent->children.begin() + from.back());
    SdfNode* group = findSdfNode(scene, target2);
    const int count = int(group->children.size());
    const int to = index < 0 || index > count ? count : index;
    group->children.insert(group->children.begin() + to, std::move(moved));
    target2.push_back(to);
    return target2;
}

int addMesh(Scene& scene, const std::filesystem::path& file) {
    MeshInstance mesh;
    mesh.name = file.stem().string();
    mesh.path = file;
    std::error_code ec;
    const std::filesystem::path base =
        scene.file.empty() ? std::filesystem::path() : scene.file.parent_path();
    std::filesystem::path relative =
        base.empty() ? file : std::filesystem::proximate(file, base, ec);
    mesh.file = (ec ? file : relative).generic_string();
    scene.meshes.push_back(std::move(mesh));
    return int(scene.meshes.size()) - 1;
}

int addLight(Scene& scene, LightType type, glm::vec3 position) {
    if (int(scene.lights.size()) >= limits::kLights) return -1;
    scene.lights.push_back(makeLight(type, position, int(scene.lights.size()) + 1));
    return int(scene.lights.size()) - 1;
}

bool deleteMesh(Scene& scene, int index) {
    if (index < 0 || index >= int(scene.meshes.size())) return false;
    scene.meshes.erase(scene.meshes.begin() + index);
    return true;
}

bool deleteLight(Scene& scene, int index) {
    if (index < 0 || index >= int(scene.lights.size())) return false;
    scene.lights.erase(scene.lights.begin() + index);
    return true;
}

int duplicateMesh(Scene& scene, int index) {
    MeshInstance copy = scene.meshes.at(std::size_t(index));
    copy.name += " copy";
    scene.meshes.insert(scene.meshes.begin() + index + 1, copy);
    return index + 1;
}

int duplicateLight(Scene& scene, int index) {
    if (int(scene.lights.size()) >= limits::kLights) return -1;
    Light copy = scene.lights.at(std::size_t(index));
    copy.name += " copy";
    scene.lights.insert(scene.lights.begin() + index + 1, copy);
    return index + 1;
}

namespace {

// Moves element `from` of `items` to position `to`, the rest keeping their order.
template <typename T> int moveWithin(std::vector<T>& items, int from, int to) {
    const int count = int(items.size());
    if (from < 0 || from >= count || to < 0 || to >= count) return -1;
    const auto first = items.begin();
    if (from < to)
        std::rotate(first + from, first + from + 1, first + to + 1);
    else
        std::rotate(first + to, first + from, first + from + 1);
    return to;
}

} // namespace

int moveMesh(Scene& scene, int from, int to) {
    return moveWithin(scene.meshes, from, to);
}

int moveLight(Scene& scene, int from, int to) {
    return moveWithin(scene.lights, from, to);
}

Selection deleteSelected(Scene& scene, const Selection& selection) {
    switch (selection.kind) {
    case SelectionKind::Sdf:
        deleteSdfNode(scene, selection.sdfPath);
        break;
    case SelectionKind::Mesh:
        deleteMesh(scene, selection.index);
        break;
    case SelectionKind::Light:
        deleteLight(scene, selection.index);
        break;
    case SelectionKind::None:
        break;
    }
    return Selection::none();
}

Selection duplicateSelected(Scene& scene, const Selection& selection) {
    if (!selectionValid(scene, selection)) return selection;
    switch (selection.kind) {
    case SelectionKind::Sdf:
        if (auto path = duplicateSdfNode(scene, selection.sdfPath)) return Selection::sdf(*path);
        return selection;
    case SelectionKind::Mesh:
        return Selection::mesh(duplicateMesh(scene, selection.index));
    case SelectionKind::Light:
        if (const int copy = duplicateLight(scene, selection.index); copy >= 0)
            return Selection::light(copy);
        return selection; // the scene has limits::kLights lights already
    case SelectionKind::None:
        break;
    }
    return selection;
}

Selection selectionForObjectId(const Scene& scene, std::uint32_t objectId) {
    if (objectId >= kSdfIdBase) {
        if (!scene.sdf) return Selection::none();
        std::uint32_t counter = 0;
        const std::uint32_t wanted = objectId - kSdfIdBase;
        std::vector<int> path;
        std::optional<std::vector<int>> found;
        std::function<void(const SdfNode&)> visit = [&](const SdfNode& node) {
            if (found) return;
            if (counter++ == wanted) {
                found = path;
                return;
            }
            for (std::size_t i = 0; i < node.children.size() && !found; ++i) {
                path.push_back(int(i));
                visit(node.children[i]);
                path.pop_back();
            }
        };
        visit(*scene.sdf);
        return found ? Selection::sdf(*found) : Selection::none();
    }
    if (objectId >= kMeshIdBase && objectId - kMeshIdBase < scene.meshes.size())
        return Selection::mesh(int(objectId - kMeshIdBase));
    return Selection::none();
}

IdRange objectIdRange(const Scene& scene, const Selection& selection) {
    if (selection.kind == SelectionKind::Mesh && selectionValid(scene, selection))
        return {kMeshIdBase + std::uint32_t(selection.index),
                kMeshIdBase + std::uint32_t(selection.index) + 1};
    if (selection.kind != SelectionKind::Sdf || !findSdfNode(scene, selection.sdfPath)) return {};
    // Pre-order index of the node: every node before it in file order.
    std::uint32_t index = 0;
    const SdfNode* node = &*scene.sdf;
    for (int i : selection.sdfPath) {
        index += 1; // the group itself
        for (int j = 0; j < i; ++j)
            index += std::uint32_t(subtreeSize(node->children[std::size_t(j)]));
        node = &node->children[std::size_t(i)];
    }
    return {kSdfIdBase + index, kSdfIdBase + index + std::uint32_t(subtreeSize(*node))};
}

namespace {

bool sameTreeShape(const SdfNode& a, const SdfNode& b) {
    if (a.children.size() != b.children.size()) return false;
    for (std::size_t i = 0; i < a.children.size(); ++i)
        if (!sameTreeShape(a.children[i], b.children[i])) return false;
    return true;
}

} // namespace

bool sameObjectIds(const Scene& a, const Scene& b) {
    if (a.meshes.size() != b.meshes.size() || a.sdf.has_value() != b.sdf.has_value()) return false;
    return !a.sdf || sameTreeShape(*a.sdf, *b.sdf);
}

std::optional<Bounds> selectionBounds(const Scene& scene, const Selection& selection) {
    if (!selectionValid(scene, selection)) return std::nullopt;
    if (selection.kind == SelectionKind::Sdf) {
        const SdfNode* node = findSdfNode(scene, selection.sdfPath);
        const glm::mat4 world = sdfWorldMatrix(scene, selection.sdfPath);
        const float scale =
            std::max({glm::length(glm::vec3(world[0])), glm::length(glm::vec3(world[1])),
                      glm::length(glm::vec3(world[2]))});
        return Bounds{glm::vec3(world[3]), localRadius(*node) * scale};
    }
    if (selection.kind == SelectionKind::Mesh) {
        const Transform& t = scene.meshes[std::size_t(selection.index)].transform;
        return Bounds{t.position, std::max(0.5f, maxComponent(t.scale))};
    }
    if (selection.kind == SelectionKind::Light)
        return Bounds{scene.lights[std::size_t(selection.index)].position, 0.5f};
    return std::nullopt;
}

std::string displayName(const SdfNode& node) {
    if (!node.name.empty()) return node.name;
    if (!node.isGroup && node.profile) return profileShapeName(*node.profile);
    if (!node.isGroup) return std::string(primitiveSpec(node.primitive).name);
    return "group";
}

} // namespace rmsc::editor
