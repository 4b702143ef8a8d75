// Loading everything a scene references, and choosing how to open a path.
#include "prepare/prepared_scene.hpp"

#include "core/limits.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/material_textures.hpp"
#include "scene/mesh_pose.hpp"
#include "scene/scene_json.hpp"
#include "sdf/bounds.hpp"
#include "sdf/compiler.hpp"

#include <algorithm>
#include <map>
#include <tuple>

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

namespace {

// Takes what a copy of `asset` holds out of the scene's budget; false when it would go over.
bool takeCopyBudget(const MeshAsset& asset, GltfBudget& budget) {
    std::uint64_t vertices = 0, indices = 0;
    for (const MeshPrimitive& p : asset.primitives) {
        vertices += p.vertices.size();
        indices += p.indices.size();
    }
    if (vertices > budget.vertices || indices > budget.indices) return false;
    budget.vertices -= vertices;
    budget.indices -= indices;
    return true;
}

// The shell's clip box and proxy mesh (object space); errors at the shell's JSON pointer.
std::optional<PreparedShell> prepareShell(SdfShellProgram compiled, const FileSource& files,
                                          const std::string& sceneFile, GltfBudget& budget,
                                          Diagnostics& diagnostics) {
    PreparedShell shell;
    shell.settings = *compiled.node->shell;
    const SdfShell& settings = shell.settings;
    const SdfBounds bounds = sdfNodeLocalBounds(*compiled.node, compiled.parentFieldScale);
    compiled.node = nullptr;
    shell.compiled = std::move(compiled);

    std::optional<ShellProxyMesh> mesh;
    glm::vec3 meshMin(0.0f), meshMax(0.0f);
    if (settings.proxy == ShellProxy::Mesh) {
        Diagnostics meshDiagnostics;
        std::optional<MeshAsset> asset =
            loadGltf(settings.meshPath, files, meshDiagnostics, budget);
        for (Diagnostic& d : meshDiagnostics.items)
            diagnostics.add({d.severity, sceneFile,
                             settings.pointer + "/mesh (\"" + settings.meshFile + "\")",
                             d.format()});
        diagnostics.addOmitted(meshDiagnostics.omittedErrors(), meshDiagnostics.omittedWarnings());
        if (!asset) return std::nullopt;
        mesh = assetProxyMesh(*asset);
        if (mesh->indices.empty()) {
            diagnostics.error(sceneFile, settings.pointer + "/mesh",
                              "\"" + settings.meshFile +
                                  "\" has no triangles to use as the shell's proxy");
            return std::nullopt;
        }
        meshMin = asset->boundsMin;
        meshMax = asset->boundsMax;
    }

    if (settings.bound) {
        shell.clipMin = -*settings.bound;
        shell.clipMax = *settings.bound;
        shell.clipsContent = true;
    } else if (bounds.bounded && !bounds.box.empty()) {
        // A margin, so the surface never touches the box (the box clips the distance, and the
        // normals there must stay the surface's) and the proxy covers hits within epsilon.
        const glm::vec3 half = bounds.box.halfSize();
        const glm::vec3 margin(0.02f * std::max({half.x, half.y, half.z}) + 1e-3f);
        shell.clipMin = bounds.box.min - margin;
        shell.clipMax = bounds.box.max + margin;
    } else if (mesh) {
        shell.clipMin = meshMin; // the user's mesh is the bound
        shell.clipMax = meshMax;
        shell.clipsContent = true;
    } else {
        diagnostics.error(
            sceneFile, settings.pointer,
            "the shell's content reaches infinity (" +
                (bounds.unboundedBy.empty() ? shell.compiled.pointer : bounds.unboundedBy) +
                "), so it has no proxy box; give \"bound\": [x, y, z] (half "
                "extents in the node's frame) to clip it, or a \"mesh\" proxy");
        return std::nullopt;
    }
    switch (settings.proxy) {
    case ShellProxy::Box:
        shell.proxy = boxProxyMesh(shell.clipMin, shell.clipMax);
        break;
    case ShellProxy::Sphere:
        shell.proxy = sphereProxyMesh(shell.clipMin, shell.clipMax);
        break;
    case ShellProxy::Mesh:
        shell.proxy = std::move(*mesh);
        break;
    }
    return shell;
}

} // namespace

std::optional<PreparedScene> prepareScene(Scene scene, const FileSource& files,
                                          Diagnostics& diagnostics, ShellMode shellMode,
                                          bool sdfBounds) {
    PreparedScene prepared;
    const int errorsBefore = diagnostics.errorCount();
    const std::string sceneFile = scene.file.string();

    // One asset per file (and glTF scene) and pose: instances showing the same file's scene at
    // the same animation and time share it; another pose of a loaded file is a copy of it, posed.
    using FileScene = std::pair<std::filesystem::path, int>;
    std::map<FileScene, int> assetByPath; // the first asset of each file's scene
    std::map<std::tuple<std::filesystem::path, int, std::string, double>, int> assetByPose;
    // Shared by the meshes, the shells' proxy meshes, the material textures and the sky image.
    GltfBudget gltfBudget;
    for (const MeshInstance& instance : scene.meshes) {
        const FileScene fileScene{instance.path, instance.gltfScene};
        const auto poseKey =
            std::make_tuple(instance.path, instance.gltfScene, instance.animation, instance.time);
        if (const auto found = assetByPose.find(poseKey); found != assetByPose.end()) {
            prepared.instanceAsset.push_back(found->second);
            continue;
        }
        std::optional<MeshAsset> asset;
        if (const auto loaded = assetByPath.find(fileScene); loaded != assetByPath.end()) {
            asset = prepared.assets[std::size_t(loaded->second)];
            if (!takeCopyBudget(*asset, gltfBudget)) {
                diagnostics.error(sceneFile, instance.pointer,
                                  "another pose of \"" + instance.file +
                                      "\" brings the scene's glTF vertices or indices over "
                                      "their limits (kSceneGltfVertices, kSceneGltfIndices)");
                prepared.instanceAsset.push_back(-1);
                continue;
            }
        } else {
            Diagnostics meshDiagnostics;
            asset = loadGltf(instance.path, files, meshDiagnostics, gltfBudget, instance.gltfScene);
            for (Diagnostic& d : meshDiagnostics.items) {
                // "scene.json: /meshes/0/file ("model.gltf"): model.gltf: /accessors/2: ..."
                // names both places.
                diagnostics.add({d.severity, sceneFile,
                                 instance.pointer + "/file (\"" + instance.file + "\")",
                                 d.format()});
            }
            diagnostics.addOmitted(meshDiagnostics.omittedErrors(),
                                   meshDiagnostics.omittedWarnings());
        }
        if (!asset) {
            prepared.instanceAsset.push_back(-1);
            continue;
        }
        MeshPose pose;
        if (instance.animation.empty() && assetByPath.count(fileScene)) {
            Diagnostics restDiagnostics; // the rest pose was baked once already: it bakes
            poseMeshAsset(*asset, pose, restDiagnostics);
        } else if (!instance.animation.empty()) {
            std::string why;
            const std::optional<int> animation =
                asset->rig ? findAnimation(*asset->rig, instance.animation, why) : std::nullopt;
            if (!animation) {
                diagnostics.error(sceneFile, instance.pointer + "/animation",
                                  "\"" + instance.file + "\": " + why);
                prepared.instanceAsset.push_back(-1);
                continue;
            }
            pose = {*animation, instance.time};
            Diagnostics poseDiagnostics;
            if (!poseMeshAsset(*asset, pose, poseDiagnostics)) {
                for (Diagnostic& d : poseDiagnostics.items)
                    diagnostics.add(
                        {d.severity, sceneFile, instance.pointer + "/animation", d.format()});
                prepared.instanceAsset.push_back(-1);
                continue;
            }
        }
        assetByPath.emplace(fileScene, int(prepared.assets.size()));
        assetByPose.emplace(poseKey, int(prepared.assets.size()));
        prepared.instanceAsset.push_back(int(prepared.assets.size()));
        prepared.assets.push_back(std::move(*asset));
        prepared.assetPoses.push_back(pose);
    }

    prepared.materials = scene.materials;
    prepared.materials.push_back(defaultMaterial());
    loadMaterialTextures(prepared.materials, sceneFile, files, diagnostics, prepared.textures,
                         &gltfBudget);
    if (scene.sdf && shellMode == ShellMode::Fullscreen) {
        std::optional<SdfProgram> program =
            compileSdf(*scene.sdf, std::uint32_t(scene.materials.size()), sceneFile, diagnostics,
                       {.bounds = sdfBounds});
        if (program) prepared.sdf = std::move(*program);
    } else if (scene.sdf) {
        std::optional<CompiledSdfScene> compiled =
            compileSdfScene(*scene.sdf, std::uint32_t(scene.materials.size()), sceneFile,
                            diagnostics, {.bounds = sdfBounds});
        if (compiled) {
            prepared.sdf = std::move(compiled->main);
            for (SdfShellProgram& shell : compiled->shells) {
                std::optional<PreparedShell> ready =
                    prepareShell(std::move(shell), files, sceneFile, gltfBudget, diagnostics);
                if (ready) prepared.shells.push_back(std::move(*ready));
            }
        }
    }
    prepared.lights = gatherLights(scene, prepared.assets, prepared.instanceAsset, diagnostics);
    if (scene.environment.sky == SkyType::Image && !scene.environment.imagePath.empty()) {
        std::optional<SkyImage> sky =
            loadSkyImage(scene.environment.imagePath, files, sceneFile, "/environment/sky/file",
                         diagnostics, &gltfBudget);
        if (sky) prepared.skyImage = std::move(*sky);
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    prepared.scene = std::move(scene);
    return prepared;
}

namespace {

// What openScene opens is also checked for its drawing cost (prepare/sdf_cost.hpp); the
// editor's own prepares of a scene it edits are not (they would prune large scenes on every
// edit).
std::optional<PreparedScene> costChecked(std::optional<PreparedScene> prepared,
                                         Diagnostics& diagnostics) {
    if (prepared && !checkSdfCost(*prepared, diagnostics)) return std::nullopt;
    return prepared;
}

} // namespace

std::optional<PreparedScene> openScene(const std::filesystem::path& path, Diagnostics& diagnostics,
                                       ShellMode shellMode, int gltfScene) {
    if (path.empty()) {
        const FileSource embedded = embeddedFileSource();
        std::optional<Scene> scene = loadScene(kDemoScenePath, embedded, diagnostics);
        if (!scene) return std::nullopt;
        return costChecked(prepareScene(std::move(*scene), embedded, diagnostics, shellMode),
                           diagnostics);
    }
    const FileSource disk = diskFileSource();
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".gltf" || extension == ".glb") {
        GltfBudget budget;
        std::optional<MeshAsset> asset = loadGltf(path, disk, diagnostics, budget, gltfScene);
        if (!asset) return std::nullopt;
        PreparedScene prepared;
        prepared.scene = sceneFromGltf(path, *asset);
        prepared.scene.meshes[0].gltfScene = gltfScene;
        prepared.assets.push_back(std::move(*asset));
        prepared.assetPoses.emplace_back();
        prepared.instanceAsset.push_back(0);
        prepared.materials = prepared.scene.materials;
        prepared.materials.push_back(defaultMaterial());
        const int errorsBefore = diagnostics.errorCount();
        prepared.lights =
            gatherLights(prepared.scene, prepared.assets, prepared.instanceAsset, diagnostics);
        if (diagnostics.errorCount() > errorsBefore) return std::nullopt; // too many lights
        return prepared;
    }
    std::optional<Scene> scene = loadScene(path, disk, diagnostics);
    if (!scene) return std::nullopt;
    return costChecked(prepareScene(std::move(*scene), disk, diagnostics, shellMode), diagnostics);
}

} // namespace rmsc
