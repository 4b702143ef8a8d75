#version 450 core
// Raster pass fragment shader: shades glTF mesh fragments with the shared lighting module and
// writes the G-buffer (colour, normal, linear view depth, object id). MASK fragments below the
// cutoff are discarded; BLEND fragments (drawn by RasterPass::drawBlended) carry their alpha.
#include "common/lighting.glsl"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;
in vec2 vUv1;
in vec4 vWorldTangent;
in vec4 vColor;

uniform vec4 uBaseColorFactor;
uniform vec4 uMetallicRoughness; // x = metallic, y = roughness, z = normal scale,
                                 // w = occlusion strength
uniform vec3 uEmissive;          // emissive factor times KHR_materials_emissive_strength
// The glTF material textures, one unit each (RasterPass binds them): the TEXCOORD set each
// reads, -1 when the material has none. 0 base colour, 1 metallic-roughness, 2 normal,
// 3 emissive, 4 occlusion.
uniform int uTexCoord[5];
// KHR_texture_transform of each of those textures (the identity without it).
uniform mat3 uUvTransform[5];
// x: alpha mode (0 OPAQUE, 1 MASK, 2 BLEND), y: alphaCutoff, z: 1 for KHR_materials_unlit.
uniform vec4 uAlpha;
uniform uint uObjectId;
layout(binding = 0) uniform sampler2D uBaseColorTexture;         // sRGB, decoded by GL
layout(binding = 1) uniform sampler2D uMetallicRoughnessTexture; // linear: B metal, G rough
layout(binding = 2) uniform sampler2D uNormalTexture;            // linear, tangent space
layout(binding = 3) uniform sampler2D uEmissiveTexture;          // sRGB, decoded by GL
layout(binding = 4) uniform sampler2D uOcclusionTexture;         // linear: R occlusion

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out float outViewDepth;
layout(location = 3) out uint outObjectId;

vec2 materialUv(int slot) {
    return (uUvTransform[slot] * vec3(uTexCoord[slot] == 1 ? vUv1 : vUv, 1.0)).xy;
}

void main() {
    // glTF 2.0 section 3.9 (Materials): every texture multiplies its factor.
    // COLOR_0 multiplies the base colour too (glTF 2.0 section 3.7.2.1).
    vec4 baseColor = uBaseColorFactor * vColor;
    if (uTexCoord[0] >= 0) baseColor *= texture(uBaseColorTexture, materialUv(0));
    // glTF 2.0 section 3.9.4: MASK keeps alpha >= alphaCutoff and draws it opaque.
    if (uAlpha.x == 1.0 && baseColor.a < uAlpha.y) discard;
    float alpha = uAlpha.x == 2.0 ? clamp(baseColor.a, 0.0, 1.0) : 1.0;
    outViewDepth = -(frame.view * vec4(vWorldPosition, 1.0)).z;
    outObjectId = uObjectId;
    if (uAlpha.z == 1.0) { // KHR_materials_unlit: the base colour, no lighting
        outColor = vec4(baseColor.rgb, alpha);
        // Lines and points without NORMAL have none: they face the camera.
        vec3 facing = dot(vWorldNormal, vWorldNormal) > 1e-12 ? normalize(vWorldNormal)
                                                              : -frame.cameraForward.xyz;
        outNormal = vec4(gl_FrontFacing ? facing : -facing, 0.0);
        return;
    }
    float metallic = uMetallicRoughness.x;
    float roughness = uMetallicRoughness.y;
    if (uTexCoord[1] >= 0) {
        vec4 mr = texture(uMetallicRoughnessTexture, materialUv(1));
        metallic *= mr.b;
        roughness *= mr.g;
    }
    vec3 emissive = uEmissive;
    if (uTexCoord[3] >= 0) emissive *= texture(uEmissiveTexture, materialUv(3)).rgb;
    float occlusion = 1.0;
    if (uTexCoord[4] >= 0) // occludedColor = lerp(color, color * occlusion, strength)
        occlusion = 1.0 + uMetallicRoughness.w * (texture(uOcclusionTexture, materialUv(4)).r - 1.0);
    vec3 normal = normalize(vWorldNormal);
    // Back faces (drawn only for double-sided materials) are lit as the other side (glTF 2.0
    // section 3.9.5): negating the mapped normal is flipping the whole frame (t, b, n).
    float side = gl_FrontFacing ? 1.0 : -1.0;
    if (uTexCoord[2] >= 0) {
        // scaledNormal = normalize((sampled * 2 - 1) * vec3(scale, scale, 1)) in the frame
        // (tangent, bitangent = cross(normal, tangent) * w, normal).
        vec3 t = vWorldTangent.xyz - normal * dot(normal, vWorldTangent.xyz);
        if (dot(t, t) > 1e-12) {
            t = normalize(t);
            vec3 b = cross(normal, t) * (vWorldTangent.w < 0.0 ? -1.0 : 1.0);
            vec3 m = texture(uNormalTexture, materialUv(2)).xyz * 2.0 - 1.0;
            m.xy *= uMetallicRoughness.z;
            normal = normalize(m.x * t + m.y * b + m.z * normal) * side;
        } else {
            normal *= side;
        }
    } else {
        normal *= side;
    }

    SurfacePoint s;
    s.position = vWorldPosition;
    s.normal = normal;
    s.baseColor = baseColor.rgb;
    s.metallic = metallic;
    s.roughness = roughness;
    s.emissive = emissive;
    s.occlusion = occlusion;

    outColor = vec4(shadeSurface(s), alpha);
    outNormal = vec4(normal, 0.0);
}
