// Scene buffers shared by every pass: materials and lights (std430). Mirrors the structs of
// engine/render/include/render/gpu_layout.hpp; the bindings and LIGHT_* types are generated.
#include "generated/constants.glsl"

// A triplanar texture of an SDF material (GpuMaterialTexture).
struct GpuMaterialTexture {
    int slot;        // texture slot (see common/material_textures.glsl), -1 = none
    float scale;     // repeats per local unit
    float sharpness; // triplanar blend exponent
    float strength;  // normal maps: x and y scale
};

struct GpuMaterial {
    vec4 baseColorMetallic; // rgb = base colour (linear), a = metallic
    vec4 emissiveRoughness; // rgb = emissive (linear), a = roughness
    GpuMaterialTexture baseColorTexture;
    GpuMaterialTexture normalTexture;
    GpuMaterialTexture roughnessTexture;
};

struct GpuLight {
    vec4 directionType;  // xyz = direction the light travels, w = LIGHT_* type
    vec4 colorIntensity; // rgb = colour (linear), a = intensity
    vec4 positionRange;  // xyz = position (point, spot), w = range (0 = unlimited)
    vec4 spotShadow;     // x, y = spot cone scale, offset; z = SDF shadow softness (0 = none);
                         // w = first shadow view (-1 = none)
};

// One layer of the shadow map array (GpuShadowView).
struct GpuShadowView {
    mat4 lightViewProjection;
    vec4 params; // x = texel world size (ortho) or per unit distance (perspective), y = perspective
};

layout(std430, binding = MATERIAL_BINDING) readonly buffer MaterialBuffer {
    GpuMaterial materials[];
};

// materials[m], for an m the caller has checked is in range. The index is clamped all the
// same: where m is a constant past the end (the empty surface's 0xffffffffu), NVIDIA's compiler
// rejects the inlined materials[m] as "array index out of bounds", even in a branch that never
// runs.
GpuMaterial materialAt(uint m) {
    return materials[min(m, uint(materials.length()) - 1u)];
}

layout(std430, binding = LIGHT_BINDING) readonly buffer LightBuffer {
    uvec4 lightHeader; // x = light count
    GpuLight lights[];
};

layout(std430, binding = SHADOW_VIEW_BINDING) readonly buffer ShadowViewBuffer {
    GpuShadowView shadowViews[];
};
