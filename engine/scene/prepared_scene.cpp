// Loading everything a scene references, and choosing how to open a path.
#include "scene/prepared_scene.hpp"

#include "scene/gltf_scene.hpp"
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"

#include <algorithm>
#include <map>

namespace rmsc {

Material defaultMaterial() {
    Material m;
    m.name = "default";
    m.baseColor = glm::vec3(0.8f);
    m.metallic = 0.0f;
    m.roughness = 0.5f;
    return m;
}

std::optional<PreparedScene> prepareScene(Scene scene, const FileSource& files,
                                          Diagnostics& diagnostics) {
    PreparedScene prepared;
    const int errorsBefore = diagnostics.errorCount();
    const std::string sceneFile = scene.file.string();

    std::map<std::filesystem::path, int> assetByPath;
    for (const MeshInstance& instance : scene.meshes) {
        auto found = assetByPath.find(instance.path);
        if (found != assetByPath.end()) {
            prepared.instanceAsset.push_back(found->second);
            continue;
        }
        Diagnostics meshDiagnostics;
        std::optional<MeshAsset> asset = loadGltf(instance.path, files, meshDiagnostics);
        for (Diagnostic& d : meshDiagnostics.items) {
            // "scene.json: /meshes/0: model.gltf: /accessors/2: ..." names both places.
            diagnostics.items.push_back({d.severity, sceneFile,
                                         instance.pointer + " (\"" + instance.file + "\")",
                                         d.format()});
        }
        if (!asset) {
            prepared.instanceAsset.push_back(-1);
            continue;
        }
        assetByPath.emplace(instance.path, int(prepared.assets.size()));
        prepared.instanceAsset.push_back(int(prepared.assets.size()));
        prepared.assets.push_back(std::move(*asset));
    }

    prepared.materials = scene.materials;
    prepared.materials.push_back(defaultMaterial());
    if (scene.sdf) {
        std::optional<SdfProgram> program =
            compileSdf(*scene.sdf, std::uint32_t(scene.materials.size()), sceneFile, diagnostics);
        if (program) prepared.sdf = std::move(*program);
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    prepared.scene = std::move(scene);
    return prepared;
}

std::optional<PreparedScene> openScene(const std::filesystem::path& path,
                                       Diagnostics& diagnostics) {
    if (path.empty()) {
        const FileSource embedded = embeddedFileSource();
        std::optional<Scene> scene = loadScene(kDemoScenePath, embedded, diagnostics);
        if (!scene) return std::nullopt;
        return prepareScene(std::move(*scene), embedded, diagnostics);
    }
    const FileSource disk = diskFileSource();
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".gltf" || extension == ".glb") {
        std::optional<MeshAsset> asset = loadGltf(path, disk, diagnostics);
        if (!asset) return std::nullopt;
        PreparedScene prepared;
        prepared.scene = sceneFromGltf(path, *asset);
        prepared.assets.push_back(std::move(*asset));
        prepared.instanceAsset.push_back(0);
        prepared.materials = prepared.scene.materials;
        prepared.materials.push_back(defaultMaterial());
        return prepared;
    }
    std::optional<Scene> scene = loadScene(path, disk, diagnostics);
    if (!scene) return std::nullopt;
    return prepareScene(std::move(*scene), disk, diagnostics);
}

} // namespace rmsc
