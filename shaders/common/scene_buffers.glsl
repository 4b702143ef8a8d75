// Scene buffers shared by every pass: materials and lights (std430). Mirrors
// engine/render/include/render/gpu_layout.hpp; binding numbers match SsboBinding there.

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

// GpuLightType (engine/render/include/render/gpu_layout.hpp).
#define LIGHT_DIRECTIONAL 0
#define LIGHT_POINT 1
#define LIGHT_SPOT 2

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

layout(std430, binding = 1) readonly buffer MaterialBuffer {
    GpuMaterial materials[];
};

layout(std430, binding = 2) readonly buffer LightBuffer {
    uvec4 lightHeader; // x = light count
    GpuLight lights[];
};

layout(std430, binding = 3) readonly buffer ShadowViewBuffer {
    GpuShadowView shadowViews[];
};
