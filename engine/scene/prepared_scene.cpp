// Loading everything a scene references, and choosing how to open a path.
#include "scene/prepared_scene.hpp"

#include "core/limits.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/material_textures.hpp"
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

std::vector<Light> gatherLights(const Scene& scene, const std::vector<MeshAsset>& assets,
                                const std::vector<int>& instanceAsset, Diagnostics& diagnostics) {
    std::vector<Light> lights = scene.lights;
    bool reported = false;
    for (std::size_t i = 0; i < scene.meshes.size() && i < instanceAsset.size(); ++i) {
        if (instanceAsset[i] < 0) continue;
        const MeshAsset& asset = assets[std::size_t(instanceAsset[i])];
        const glm::mat4 model = scene.meshes[i].transform.matrix();
        for (Light light : asset.lights) {
            if (int(lights.size()) >= limits::kLights) {
                if (!reported) {
                    diagnostics.error(scene.file.string(), scene.meshes[i].pointer,
                                      "\"" + scene.meshes[i].file +
                                          "\" brings KHR_lights_punctual lights that make the "
                                          "scene's lights more than " +
                                          std::to_string(limits::kLights) + " (the limit)");
                }
                reported = true;
                break;
            }
            light.position = glm::vec3(model * glm::vec4(light.position, 1.0f));
            const glm::vec3 direction = glm::mat3(model) * light.direction;
            if (glm::length(direction) > 0.0f) light.direction = glm::normalize(direction);
            lights.push_back(light);
        }
    }
    return lights;
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
    loadMaterialTextures(prepared.materials, sceneFile, files, diagnostics, prepared.textures);
    if (scene.sdf) {
        std::optional<SdfProgram> program =
            compileSdf(*scene.sdf, std::uint32_t(scene.materials.size()), sceneFile, diagnostics);
        if (program) prepared.sdf = std::move(*program);
    }
    prepared.lights = gatherLights(scene, prepared.assets, prepared.instanceAsset, diagnostics);
    if (scene.environment.sky == SkyType::Image && !scene.environment.imagePath.empty()) {
        std::optional<SkyImage> sky = loadSkyImage(scene.environment.imagePath, files, sceneFile,
                                                   "/environment/sky/file", diagnostics);
        if (sky) prepared.skyImage = std::move(*sky);
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
        prepared.lights =
            gatherLights(prepared.scene, prepared.assets, prepared.instanceAsset, diagnostics);
        return prepared;
    }
    std::optional<Scene> scene = loadScene(path, disk, diagnostics);
    if (!scene) return std::nullopt;
    return prepareScene(std::move(*scene), disk, diagnostics);
}

} // namespace rmsc
