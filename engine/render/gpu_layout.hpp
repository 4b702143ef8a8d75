// The std430 structs of the scene buffers shared by every pass (materials, lights), mirrored in
// shaders/common/scene_buffers.glsl, and the binding points of all shader storage buffers.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace rmsc {

// SSBO binding points, the same numbers as in shaders/common/scene_buffers.glsl.
enum SsboBinding : unsigned { kSdfProgramBinding = 0, kMaterialBinding = 1, kLightBinding = 2 };

struct GpuMaterial {
    glm::vec4 baseColorMetallic;   // rgb = base colour (linear), a = metallic
    glm::vec4 emissiveRoughness;   // rgb = emissive (linear), a = roughness
};
static_assert(sizeof(GpuMaterial) == 32);

struct GpuLight {
    glm::vec4 directionType;  // xyz = direction the light travels (normalized), w = type (0 = dir.)
    glm::vec4 colorIntensity; // rgb = linear colour, a = intensity
};
static_assert(sizeof(GpuLight) == 32);
static_assert(offsetof(GpuLight, colorIntensity) == 16);

// Header of the light buffer, before the array.
struct GpuLightHeader {
    glm::uvec4 count; // x = number of lights
};

// The scene's materials followed by the default material (used where none is named); the
// default's index is scene.materials.size().
std::vector<GpuMaterial> packMaterials(const std::vector<Material>& materials);
std::vector<GpuLight> packLights(const std::vector<Light>& lights);
GpuMaterial packMaterial(const Material& m);

} // namespace rmsc
