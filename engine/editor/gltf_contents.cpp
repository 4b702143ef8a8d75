// The animations, cameras and scenes of a mesh's glTF file (see gltf_contents.hpp).
#include "editor/gltf_contents.hpp"

#include "scene/gltf_cameras.hpp"

namespace rmsc::editor {

namespace {

std::string label(std::size_t index, const std::string& name) {
    return name.empty() ? std::to_string(index) : std::to_string(index) + " " + name;
}

// The asset drawn for mesh instance `mesh`, or nullptr.
const MeshAsset* assetOf(const PreparedScene& prepared, int mesh, int* assetIndex = nullptr) {
    if (mesh < 0 || std::size_t(mesh) >= prepared.instanceAsset.size()) return nullptr;
    const int a = prepared.instanceAsset[std::size_t(mesh)];
    if (a < 0 || std::size_t(a) >= prepared.assets.size()) return nullptr;
    if (assetIndex) *assetIndex = a;
    return prepared.assets[std::size_t(a)].rig ? &prepared.assets[std::size_t(a)] : nullptr;
}

} // namespace

std::optional<GltfContents> gltfContents(const PreparedScene& prepared, int mesh) {
    int a = -1;
    const MeshAsset* asset = assetOf(prepared, mesh, &a);
    if (!asset) return std::nullopt;
    const MeshRig& rig = *asset->rig;
    GltfContents out;
    for (std::size_t i = 0; i < rig.animations.size(); ++i) {
        out.animations.push_back(label(i, rig.animations[i].name));
        out.durations.push_back(double(rig.animations[i].duration));
    }
    for (std::size_t i = 0; i < rig.cameras.size(); ++i)
        out.cameras.push_back(label(i, rig.cameras[i].name) +
                              (rig.cameras[i].orthographic ? " (orthographic)" : ""));
    for (std::size_t i = 0; i < rig.sceneNames.size(); ++i)
        out.scenes.push_back(label(i, rig.sceneNames[i]));
    out.scene = rig.scene;
    if (std::size_t(a) < prepared.assetPoses.size())
        out.animation = prepared.assetPoses[std::size_t(a)].animation;
    return out;
}

std::optional<Camera> gltfCameraView(const PreparedScene& prepared, int mesh, int camera,
                                     std::string& why) {
    int a = -1;
    const MeshAsset* asset = assetOf(prepared, mesh, &a);
    if (!asset) {
        why = "the mesh's file did not load";
        return std::nullopt;
    }
    const MeshPose pose = std::size_t(a) < prepared.assetPoses.size()
                              ? prepared.assetPoses[std::size_t(a)]
                              : MeshPose{};
    std::optional<Camera> view = gltfCameraAt(*asset->rig, camera, pose, why);
    if (!view) return std::nullopt;
    const glm::mat4 m = prepared.scene.meshes[std::size_t(mesh)].transform.matrix();
    const glm::vec3 up = glm::mat3(m) * glm::normalize(view->up);
    const float scale = glm::length(up);
    view->position = glm::vec3(m * glm::vec4(view->position, 1.0f));
    view->target = glm::vec3(m * glm::vec4(view->target, 1.0f));
    view->up = up / scale;
    view->nearPlane *= scale;
    view->farPlane *= scale;
    view->orthoHeight *= scale;
    return view;
}

} // namespace rmsc::editor
