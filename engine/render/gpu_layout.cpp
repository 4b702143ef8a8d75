// Packing scene materials and lights into their std430 layouts.
#include "render/gpu_layout.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {

namespace {

GpuMaterialTexture packTexture(const MaterialTexture& t) {
    GpuMaterialTexture out;
    out.slot = t.present() ? t.image : -1;
    out.scale = t.scale;
    out.sharpness = t.sharpness;
    out.strength = t.strength;
    return out;
}

} // namespace

GpuMaterial packMaterial(const Material& m) {
    return {glm::vec4(m.baseColor, m.metallic), glm::vec4(m.emissive, m.roughness),
            packTexture(m.baseColorTexture), packTexture(m.normalTexture),
            packTexture(m.roughnessTexture)};
}

std::vector<GpuMaterial> packMaterials(const std::vector<Material>& materials) {
    std::vector<GpuMaterial> packed;
    for (const Material& m : materials)
        packed.push_back(packMaterial(m));
    return packed;
}

std::vector<GpuLight> packLights(const std::vector<Light>& lights, bool shadowsEnabled,
                                 float defaultSoftness) {
    std::vector<GpuLight> packed;
    for (const Light& light : lights) {
        GpuLight gpu{};
        int type = kGpuDirectional;
        if (light.type == LightType::Point) type = kGpuPoint;
        if (light.type == LightType::Spot) type = kGpuSpot;
        gpu.directionType = glm::vec4(glm::normalize(light.direction), float(type));
        gpu.colorIntensity = glm::vec4(light.color, light.intensity);
        gpu.positionRange = glm::vec4(light.position, std::max(light.range, 0.0f));
        // KHR_lights_punctual, "Inner and Outer Cone Angles": the cone blends with
        // saturate(cd * scale + offset)^2 where cd is the cosine of the angle to the axis.
        const float cosOuter = std::cos(glm::radians(light.outerAngleDegrees));
        const float cosInner = std::cos(glm::radians(light.innerAngleDegrees));
        const float scale = 1.0f / std::max(0.001f, cosInner - cosOuter);
        const float softness = light.shadowSoftness > 0.0f ? light.shadowSoftness : defaultSoftness;
        gpu.spotShadow = glm::vec4(scale, -cosOuter * scale,
                                   shadowsEnabled && light.castShadows ? softness : 0.0f, -1.0f);
        packed.push_back(gpu);
    }
    return packed;
}

} // namespace rmsc
