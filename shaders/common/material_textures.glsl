// Textures of SDF materials: triplanar projection in the shape's local space, so a texture
// moves, turns and scales with its shape. Base colour (sRGB texture, decoded by GL), roughness
// (green channel) and tangent-space normal maps. The textures are bound one per texture unit
// from SDF_TEXTURE_FIRST_UNIT on (kSdfMaterialTextureFirstUnit in engine/render/include/render/gpu_layout.hpp):
// GLSL 4.50 only allows dynamically uniform indices into sampler arrays and a material index
// varies per pixel, so a switch picks the sampler. Each texture keeps its own size.
//
// Triplanar mapping and the normal-map blend: Ben Golus, "Normal Mapping for a Triplanar
// Shader" (2017), https://bgolus.medium.com/normal-mapping-for-a-triplanar-shader-10bf39dca05a
// -- blend weights |n|^sharpness normalized to sum 1, one planar projection per axis with its
// tangent flipped on the negative side so no face is mirrored, and the "whiteout" blend
// (tangent-space xy added to the surface normal's in-plane part, z multiplied) per projection.
// Here each projection has an explicit right-handed frame (tangent T, bitangent B, axis A with
// T x B = A) so the map's +x points along T and its +y (up the image) along B.
#include "generated/constants.glsl"
#include "common/scene_buffers.glsl"

// One sampler per texture slot, SDF_TEXTURE_COUNT of them (picked by sampleSdfTexture).
#if SDF_TEXTURE_COUNT != 8
#error "declare one uSdfTexture per slot (SDF_TEXTURE_COUNT)"
#endif
layout(binding = SDF_TEXTURE_FIRST_UNIT + 0) uniform sampler2D uSdfTexture0;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 1) uniform sampler2D uSdfTexture1;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 2) uniform sampler2D uSdfTexture2;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 3) uniform sampler2D uSdfTexture3;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 4) uniform sampler2D uSdfTexture4;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 5) uniform sampler2D uSdfTexture5;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 6) uniform sampler2D uSdfTexture6;
layout(binding = SDF_TEXTURE_FIRST_UNIT + 7) uniform sampler2D uSdfTexture7;

// Samples with an explicit level of detail: the hit is found in non-uniform control flow, where
// implicit derivatives are undefined. `footprint` is a pixel's size in texture repeats.
vec4 sampleFootprint(sampler2D t, vec2 uv, float footprint) {
    vec2 size = vec2(textureSize(t, 0));
    float lod = log2(max(footprint * max(size.x, size.y), 1e-6));
    return textureLod(t, uv, lod);
}

vec4 sampleSdfTexture(int slot, vec2 uv, float footprint) {
    switch (slot) {
    case 0: return sampleFootprint(uSdfTexture0, uv, footprint);
    case 1: return sampleFootprint(uSdfTexture1, uv, footprint);
    case 2: return sampleFootprint(uSdfTexture2, uv, footprint);
    case 3: return sampleFootprint(uSdfTexture3, uv, footprint);
    case 4: return sampleFootprint(uSdfTexture4, uv, footprint);
    case 5: return sampleFootprint(uSdfTexture5, uv, footprint);
    case 6: return sampleFootprint(uSdfTexture6, uv, footprint);
    case 7: return sampleFootprint(uSdfTexture7, uv, footprint);
    }
    return vec4(1.0);
}

// The projection frame of axis 0 (x), 1 (y) or 2 (z) on the side `s` (+1 or -1) of the
// local normal: T x B = s * axis. The same frames are used by tests (CPU expectations).
void triplanarFrame(int axis, float s, out vec3 T, out vec3 B, out vec3 A) {
    if (axis == 0) {
        T = vec3(0.0, 0.0, -s);
        B = vec3(0.0, 1.0, 0.0);
        A = vec3(s, 0.0, 0.0);
    } else if (axis == 1) {
        T = vec3(s, 0.0, 0.0);
        B = vec3(0.0, 0.0, -1.0);
        A = vec3(0.0, s, 0.0);
    } else {
        T = vec3(s, 0.0, 0.0);
        B = vec3(0.0, 1.0, 0.0);
        A = vec3(0.0, 0.0, s);
    }
}

vec3 triplanarWeights(vec3 n, float sharpness) {
    vec3 w = pow(abs(n), vec3(sharpness));
    return w / max(w.x + w.y + w.z, 1e-8);
}

// Texture coordinates of local point q in a projection: u along T, v down the image (-B).
vec2 triplanarUv(vec3 q, vec3 T, vec3 B, float scale) {
    return vec2(dot(q, T), -dot(q, B)) * scale;
}

// The blended texture value at local point q with local unit normal n.
vec4 triplanarSample(GpuMaterialTexture tex, vec3 q, vec3 n, float localFootprint) {
    vec3 w = triplanarWeights(n, tex.sharpness);
    vec4 sum = vec4(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        if (w[axis] < 1e-3) continue;
        vec3 T, B, A;
        triplanarFrame(axis, n[axis] < 0.0 ? -1.0 : 1.0, T, B, A);
        sum += w[axis] * sampleSdfTexture(tex.slot, triplanarUv(q, T, B, tex.scale),
                                          localFootprint * tex.scale);
    }
    return sum / max(w.x * float(w.x >= 1e-3) + w.y * float(w.y >= 1e-3) +
                         w.z * float(w.z >= 1e-3), 1e-8);
}

// The local normal n bent by the tangent-space normal map, whiteout-blended per projection.
vec3 triplanarNormal(GpuMaterialTexture tex, vec3 q, vec3 n, float localFootprint) {
    vec3 w = triplanarWeights(n, tex.sharpness);
    vec3 sum = vec3(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        if (w[axis] < 1e-3) continue;
        vec3 T, B, A;
        triplanarFrame(axis, n[axis] < 0.0 ? -1.0 : 1.0, T, B, A);
        vec3 tn = sampleSdfTexture(tex.slot, triplanarUv(q, T, B, tex.scale),
                                   localFootprint * tex.scale).xyz * 2.0 - 1.0;
        tn.xy *= tex.strength;
        sum += w[axis] * (T * (tn.x + dot(n, T)) + B * (tn.y + dot(n, B)) +
                          A * (abs(tn.z) * abs(dot(n, A))));
    }
    float len = length(sum);
    return len > 0.0 ? sum / len : n;
}

bool materialHasTextures(uint m) {
    if (m >= uint(materials.length())) return false;
    GpuMaterial material = materialAt(m);
    return material.baseColorTexture.slot >= 0 || material.normalTexture.slot >= 0 ||
           material.roughnessTexture.slot >= 0;
}

bool materialHasNormalTexture(uint m) {
    return m < uint(materials.length()) && materialAt(m).normalTexture.slot >= 0;
}

// Applies material m's textures at local point q (local unit normal n; a pixel covers
// localFootprint local units): multiplies baseColor and roughness, and bends n when the
// material has a normal map.
void applyMaterialTextures(uint m, vec3 q, float localFootprint, inout vec3 n,
                           inout vec3 baseColor, inout float roughness) {
    if (m >= uint(materials.length())) return;
    GpuMaterial material = materialAt(m);
    if (material.baseColorTexture.slot >= 0)
        baseColor *= triplanarSample(material.baseColorTexture, q, n, localFootprint).rgb;
    if (material.roughnessTexture.slot >= 0)
        roughness *= triplanarSample(material.roughnessTexture, q, n, localFootprint).g;
    if (material.normalTexture.slot >= 0)
        n = triplanarNormal(material.normalTexture, q, n, localFootprint);
}
