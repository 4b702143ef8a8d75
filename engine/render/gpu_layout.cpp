// Packing scene materials and lights into their std430 layouts.
#include "render/gpu_layout.hpp"

namespace rmsc {

GpuMaterial packMaterial(const Material& m) {
    return {glm::vec4(m.baseColor, m.metallic), glm::vec4(m.emissive, m.roughness)};
}

std::vector<GpuMaterial> packMaterials(const std::vector<Material>& materials) {
    std::vector<GpuMaterial> packed;
    for (const Material& m : materials) packed.push_back(packMaterial(m));
    return packed;
}

std::vector<GpuLight> packLights(const std::vector<Light>& lights) {
    std::vector<GpuLight> packed;
    for (const Light& light : lights) {
        packed.push_back({glm::vec4(glm::normalize(light.direction), 0.0f),
                          glm::vec4(light.color, light.intensity)});
    }
    return packed;
}

} // namespace rmsc
