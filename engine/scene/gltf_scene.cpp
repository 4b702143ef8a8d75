// A scene for viewing one glTF file (see gltf_scene.hpp).
#include "scene/gltf_scene.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {

Scene sceneFromGltf(const std::filesystem::path& gltfPath, const MeshAsset& asset) {
    Scene scene;
    scene.file = gltfPath;

    MeshInstance instance;
    instance.name = gltfPath.stem().string();
    instance.file = gltfPath.filename().string();
    instance.path = gltfPath;
    instance.pointer = "/meshes/0";
    scene.meshes.push_back(instance);

    Light sun;
    sun.name = "sun";
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    sun.intensity = 3.0f;
    scene.lights.push_back(sun);
    // A neutral studio around a model opened by itself (scenes keep their own environment), as
    // glTF viewers show one by default: a grey gradient sky, bright above, dark below, that
    // lights every surface from all sides (the fill to the sun's key) and gives metals
    // something to reflect.
    Environment& studio = scene.environment;
    studio.sky = SkyType::Gradient;
    studio.zenith = glm::vec3(0.9f);
    studio.horizon = glm::vec3(0.5f);
    studio.ground = glm::vec3(0.18f);
    studio.intensity = 0.8f;

    // Fit the bounding sphere into the vertical field of view, with 20% to spare.
    const glm::vec3 centre = 0.5f * (asset.boundsMin + asset.boundsMax);
    float radius = 0.5f * glm::length(asset.boundsMax - asset.boundsMin);
    if (!(radius > 1e-4f) || !std::isfinite(radius)) radius = 1.0f;
    Camera& camera = scene.camera;
    camera.fovYDegrees = 45.0f;
    const float halfFov = glm::radians(camera.fovYDegrees) * 0.5f;
    const float distance = 1.2f * radius / std::sin(halfFov);
    const glm::vec3 viewFrom = glm::normalize(glm::vec3(0.0f, 0.5f, 1.0f)); // +z, a bit above
    camera.target = centre;
    camera.position = centre + viewFrom * distance;
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.nearPlane = std::max(distance - radius, distance * 0.01f) * 0.1f;
    camera.farPlane = (distance + radius) * 4.0f;
    return scene;
}

} // namespace rmsc
