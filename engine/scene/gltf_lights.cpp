// Reading KHR_lights_punctual lights (Khronos extension specification): type, colour,
// intensity (lux for directional, candela for point and spot), range, spot cone angles in
// radians; position from the node's translation, direction its -Z axis.
#include "gltf_lights.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::gltf {

void addNodeLight(const tinygltf::Model& model, const tinygltf::Node& node, const glm::dmat4& world,
                  const std::string& nodePointer, Reporter& report, MeshAsset& asset) {
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) return;
    const std::string extPointer = nodePointer + "/extensions/KHR_lights_punctual";
    if (!ext->second.IsObject() || !ext->second.Has("light") ||
        !ext->second.Get("light").IsNumber()) {
        report.error(extPointer, "expected {\"light\": <index into the lights>}");
        return;
    }
    const double index = ext->second.Get("light").GetNumberAsDouble();
    if (!(index >= 0.0) || index >= double(model.lights.size()) || index != std::floor(index)) {
        report.error(extPointer + "/light", "refers to a missing light (the file defines " +
                                                std::to_string(model.lights.size()) + ")");
        return;
    }
    const std::size_t lightIndex = std::size_t(index);
    const tinygltf::Light& source = model.lights[lightIndex];
    const std::string pointer =
        "/extensions/KHR_lights_punctual/lights/" + std::to_string(lightIndex);
    Light light;
    light.name = source.name;
    if (source.type == "directional") {
        light.type = LightType::Directional;
    } else if (source.type == "point") {
        light.type = LightType::Point;
    } else if (source.type == "spot") {
        light.type = LightType::Spot;
    } else {
        report.error(pointer + "/type", "unknown light type \"" + source.type +
                                            "\"; expected \"directional\", \"point\" or \"spot\"");
        return;
    }
    bool ok = true;
    if (!source.color.empty()) {
        if (source.color.size() != 3 ||
            std::any_of(source.color.begin(), source.color.end(),
                        [](double c) { return !(c >= 0.0) || !std::isfinite(c); })) {
            report.error(pointer + "/color", "expected 3 finite numbers >= 0");
            ok = false;
        } else {
            light.color =
                glm::vec3(float(source.color[0]), float(source.color[1]), float(source.color[2]));
        }
    }
    if (!(source.intensity >= 0.0) || !std::isfinite(source.intensity)) {
        report.error(pointer + "/intensity", "expected a finite number >= 0");
        ok = false;
    }
    light.intensity = float(source.intensity);
    if (!(source.range >= 0.0) || !std::isfinite(source.range)) {
        report.error(pointer + "/range", "expected a number > 0");
        ok = false;
    }
    light.range = float(source.range);
    if (light.type == LightType::Spot) {
        const double inner = source.spot.innerConeAngle, outer = source.spot.outerConeAngle;
        const double quarter = 0.5 * 3.14159265358979323846;
        if (!(outer > 0.0 && outer <= quarter + 1e-6)) {
            report.error(pointer + "/spot/outerConeAngle",
                         "expected a number in (0, pi/2] radians");
            ok = false;
        } else if (!(inner >= 0.0 && inner < outer)) {
            report.error(pointer + "/spot/innerConeAngle",
                         "expected a number in [0, outerConeAngle) radians");
            ok = false;
        }
        light.innerAngleDegrees = float(inner * 180.0 / 3.14159265358979323846);
        light.outerAngleDegrees = float(std::min(outer, quarter) * 180.0 / 3.14159265358979323846);
    }
    if (!ok) return;
    light.position = glm::vec3(world[3]);
    const glm::dvec3 down = glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    light.direction =
        glm::length(down) > 0.0 ? glm::vec3(glm::normalize(down)) : glm::vec3(0.0f, 0.0f, -1.0f);
    asset.lights.push_back(light);
}

} // namespace rmsc::gltf
