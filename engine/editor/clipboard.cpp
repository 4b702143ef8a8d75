// Copy and paste as scene-file text (see clipboard.hpp).
#include "editor/clipboard.hpp"

#include "core/limits.hpp"
#include "editor/scene_check.hpp"
#include "editor/scene_edits.hpp"
#include "editor/selection_edits.hpp"
#include "editor/world_placement.hpp"
#include "scene/scene_json.hpp"
#include "scene/scene_paths.hpp"

#include <filesystem>
#include <functional>
#include <map>

namespace rmsc::editor {
namespace {

namespace fs = std::filesystem;

// Rewrites the material indices of `node`'s subtree through `remap` (from -> to).
void remapMaterials(SdfNode& node, const std::function<int(int)>& remap) {
    if (node.material >= 0) node.material = remap(node.material);
    for (SdfNode& child : node.children)
        remapMaterials(child, remap);
}

// The identity transform, no modifiers, no material, no shell: a root that only collects.
bool isPlainUnionRoot(const SdfNode& root) {
    const Transform identity;
    return root.isGroup && root.op == SdfOp::Union && !root.cut && root.material < 0 &&
           root.modifiers.empty() && !root.shell && root.transform.position == identity.position &&
           root.transform.rotation == identity.rotation && root.transform.scale == identity.scale;
}

} // namespace

std::string clipboardText(const Scene& scene, const std::vector<Selection>& items) {
    Scene clip;
    clip.file = scene.file;
    std::map<int, int> materials; // scene index -> clip index
    const std::function<int(int)> keep = [&](int index) {
        if (index < 0 || index >= int(scene.materials.size())) return -1;
        auto [it, added] = materials.emplace(index, int(clip.materials.size()));
        if (added) clip.materials.push_back(scene.materials[std::size_t(index)]);
        return it->second;
    };
    const std::vector<std::vector<int>> paths = outermostSdfPaths(scene, items);
    if (!paths.empty()) {
        SdfNode root;
        root.isGroup = true;
        root.op = SdfOp::Union;
        for (const std::vector<int>& path : paths) {
            SdfNode node = *findSdfNode(scene, path);
            node.transform = transformFromMatrix(sdfWorldMatrix(scene, path));
            node.material = effectiveMaterial(scene, path);
            node.cut = false; // it cut its old siblings; in the clip it has none
            remapMaterials(node, keep);
            root.children.push_back(std::move(node));
        }
        clip.sdf = std::move(root);
    }
    for (const Selection& item : items) {
        if (item.kind == SelectionKind::Mesh && item.index >= 0 &&
            item.index < int(scene.meshes.size())) {
            MeshInstance mesh = scene.meshes[std::size_t(item.index)];
            mesh.materialOverride = keep(mesh.materialOverride);
            clip.meshes.push_back(std::move(mesh));
        }
        if (item.kind == SelectionKind::Light && item.index >= 0 &&
            item.index < int(scene.lights.size()))
            clip.lights.push_back(scene.lights[std::size_t(item.index)]);
    }
    if (!clip.sdf && clip.meshes.empty() && clip.lights.empty()) return "";
    // Absolute paths: the text is read back wherever it is pasted.
    forEachScenePath(clip, [](const ScenePath& p) {
        if (p.file.empty()) return;
        p.path = fs::absolute(p.path).lexically_normal();
        p.file = p.path.generic_string();
    });
    return sceneToJson(clip);
}

std::optional<Scene> parseClipboardText(std::string_view text, std::string& error) {
    const std::size_t start = text.find_first_not_of(" \t\r\n");
    if (start == std::string_view::npos || text[start] != '{') {
        error = "the clipboard holds no scene objects (copy some with Ctrl+C)";
        return std::nullopt;
    }
    Diagnostics problems;
    std::optional<Scene> clip = parseScene(text, "clipboard", problems);
    if (!clip) {
        error = "the clipboard's text is not a valid scene, so nothing was pasted:\n" +
                firstErrors(problems);
        return std::nullopt;
    }
    return clip;
}

PasteResult pasteClip(Scene& scene, const Selection& near, const Scene& source) {
    Scene clip = source;
    if (!scene.file.empty()) {
        const fs::path folder = fs::absolute(scene.file).parent_path();
        forEachScenePath(clip, [&](const ScenePath& p) {
            if (!p.file.empty()) p.file = p.path.lexically_proximate(folder).generic_string();
        });
    }
    const std::function<int(int)> matchMaterial = [&](int index) {
        if (index < 0 || index >= int(clip.materials.size())) return -1;
        const Material& material = clip.materials[std::size_t(index)];
        for (std::size_t i = 0; i < scene.materials.size(); ++i)
            if (!material.name.empty() && scene.materials[i].name == material.name) return int(i);
        scene.materials.push_back(material);
        return int(scene.materials.size()) - 1;
    };
    PasteResult result;
    std::vector<SdfNode> nodes;
    if (clip.sdf) {
        if (isPlainUnionRoot(*clip.sdf))
            nodes = clip.sdf->children;
        else
            nodes.push_back(*clip.sdf);
    }
    std::vector<int> parent;
    int next = 0; // where the next node goes in `parent`
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        SdfNode node = std::move(nodes[i]);
        remapMaterials(node, matchMaterial);
        std::vector<int> path;
        if (i == 0) {
            path = insertSdfNode(scene, near, std::move(node));
            parent.assign(path.begin(), path.end() - 1);
            next = path.back() + 1;
        } else {
            SdfNode* group = findSdfNode(scene, parent);
            group->children.insert(group->children.begin() + next, std::move(node));
            path = parent;
            path.push_back(next++);
        }
        // The clip holds world placements; the new parent may have a transform of its own.
        SdfNode* placed = findSdfNode(scene, path);
        placed->transform = transformFromMatrix(glm::inverse(sdfWorldMatrix(scene, parent)) *
                                                placed->transform.matrix());
        result.pasted.push_back(Selection::sdf(path));
    }
    for (MeshInstance& mesh : clip.meshes) {
        mesh.materialOverride = matchMaterial(mesh.materialOverride);
        scene.meshes.push_back(std::move(mesh));
        result.pasted.push_back(Selection::mesh(int(scene.meshes.size()) - 1));
    }
    for (const Light& light : clip.lights) {
        if (int(scene.lights.size()) >= limits::kLights) {
            ++result.lightsLeftOut;
            continue;
        }
        scene.lights.push_back(light);
        result.pasted.push_back(Selection::light(int(scene.lights.size()) - 1));
    }
    return result;
}

} // namespace rmsc::editor
