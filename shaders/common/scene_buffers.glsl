// Scene buffers shared by every pass: materials and lights (std430). Mirrors
// engine/render/gpu_layout.hpp; binding numbers match SsboBinding there.

struct GpuMaterial {
    vec4 baseColorMetallic; // rgb = base colour (linear), a = metallic
    vec4 emissiveRoughness; // rgb = emissive (linear), a = roughness
};

struct GpuLight {
    vec4 directionType;  // xyz = direction the light travels, w = type (0 = directional)
    vec4 colorIntensity; // rgb = colour (linear), a = intensity
};

layout(std430, binding = 1) readonly buffer MaterialBuffer {
    GpuMaterial materials[];
};

layout(std430, binding = 2) readonly buffer LightBuffer {
    uvec4 lightHeader; // x = light count
    GpuLight lights[];
};
