// glTF cameras as rmsc cameras (see gltf_cameras.hpp).
#include "scene/gltf_cameras.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rmsc {

std::string describeGltfCameras(const MeshRig& rig) {
    std::string out;
    for (std::size_t c = 0; c < rig.cameras.size(); ++c) {
        const RigCamera& camera = rig.cameras[c];
        out += (c ? ", " : "") + std::to_string(c);
        if (!camera.name.empty()) out += " \"" + camera.name + "\"";
        if (camera.orthographic) out += " (orthographic)";
    }
    return out;
}

std::optional<int> findGltfCamera(const MeshRig& rig, const std::string& nameOrIndex,
                                  std::string& why) {
    for (std::size_t c = 0; c < rig.cameras.size(); ++c)
        if (rig.cameras[c].name == nameOrIndex) return int(c);
    const bool number = !nameOrIndex.empty() && nameOrIndex.size() < 10 &&
                        std::all_of(nameOrIndex.begin(), nameOrIndex.end(),
                                    [](unsigned char ch) { return std::isdigit(ch); });
    if (number && std::stoul(nameOrIndex) < rig.cameras.size()) return int(std::stoul(nameOrIndex));
    why = "there is no camera \"" + nameOrIndex + "\"; the file has " +
          (rig.cameras.empty() ? std::string("no cameras") : "cameras " + describeGltfCameras(rig));
    return std::nullopt;
}

std::optional<Camera> gltfCameraAt(const MeshRig& rig, int index, const MeshPose& pose,
                                   std::string& why) {
    const RigCamera& camera = rig.cameras.at(std::size_t(index));
    const std::string name =
        "camera " + std::to_string(index) + (camera.name.empty() ? "" : " \"" + camera.name + "\"");
    if (camera.node < 0) {
        why = name + " is not placed by any node of the scene drawn";
        return std::nullopt;
    }
    const glm::dmat4 world = poseNodeWorlds(rig, pose)[std::size_t(camera.node)];
    const glm::dvec3 position(world[3]);
    const glm::dvec3 forward = glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const glm::dvec3 up = glm::dvec3(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
    if (!(glm::length(forward) > 1e-12) || !(glm::length(up) > 1e-12) ||
        !(glm::length(glm::cross(forward, up)) > 1e-12)) {
        why = name + ": its node's transform is degenerate (no view direction)";
        return std::nullopt;
    }
    Camera out;
    out.position = glm::vec3(position);
    out.target = glm::vec3(position + glm::normalize(forward));
    out.up = glm::vec3(glm::normalize(up));
    out.nearPlane = float(camera.znear);
    if (camera.orthographic) {
        // glTF's ymag is half the view's height (its xmag is not used: the image's own aspect
        // gives the width, as it does for a perspective camera's aspectRatio).
        out.projection = CameraProjection::Orthographic;
        out.orthoHeight = float(2.0 * camera.ymag);
        out.farPlane = float(camera.zfar);
        return out;
    }
    out.fovYDegrees = float(glm::degrees(camera.yfov));
    // An infinite far plane (no zfar) is drawn out to 100,000 times the near distance.
    out.farPlane = float(camera.zfar > 0.0 ? camera.zfar : camera.znear * 1e5);
    return out;
}

} // namespace rmsc
