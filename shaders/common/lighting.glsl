// Shading shared by every pass: the glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification,
// Appendix B "BRDF Implementation"): Lambertian diffuse plus a GGX / Trowbridge-Reitz
// microfacet specular with the height-correlated Smith visibility term and Schlick's Fresnel,
// summed over the scene's lights, plus a constant ambient term.
#include "common/frame.glsl"
#include "common/scene_buffers.glsl"

const float PI = 3.14159265358979;

struct SurfacePoint {
    vec3 position;  // world
    vec3 normal;    // world, normalized, facing the viewer
    vec3 baseColor; // linear
    float metallic;
    float roughness; // perceptual roughness; alpha = roughness^2
    vec3 emissive;
};

// Trowbridge-Reitz / GGX normal distribution.
float distributionGgx(float nDotH, float alpha) {
    float a2 = alpha * alpha;
    float d = nDotH * nDotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// Height-correlated Smith visibility V = G / (4 n.l n.v) (Heitz 2014, as in the glTF spec).
float visibilitySmithGgx(float nDotL, float nDotV, float alpha) {
    float a2 = alpha * alpha;
    float gv = nDotL * sqrt(nDotV * nDotV * (1.0 - a2) + a2);
    float gl = nDotV * sqrt(nDotL * nDotL * (1.0 - a2) + a2);
    float g = gv + gl;
    return g > 0.0 ? 0.5 / g : 0.0;
}

vec3 fresnelSchlick(vec3 f0, float vDotH) {
    return f0 + (1.0 - f0) * pow(1.0 - vDotH, 5.0);
}

// Radiance reflected towards the eye from light arriving along -lightDir with `irradiance`.
vec3 brdfDirect(SurfacePoint s, vec3 toEye, vec3 toLight, vec3 irradiance) {
    float nDotL = dot(s.normal, toLight);
    if (nDotL <= 0.0) return vec3(0.0);
    float nDotV = max(dot(s.normal, toEye), 1e-4);
    vec3 h = normalize(toLight + toEye);
    float nDotH = max(dot(s.normal, h), 0.0);
    float vDotH = max(dot(toEye, h), 0.0);
    float roughness = clamp(s.roughness, 0.03, 1.0);
    float alpha = roughness * roughness;
    vec3 f0 = mix(vec3(0.04), s.baseColor, s.metallic);
    vec3 f = fresnelSchlick(f0, vDotH);
    vec3 diffuse = (1.0 - f) * (1.0 - s.metallic) * s.baseColor / PI;
    vec3 specular = f * distributionGgx(nDotH, alpha) * visibilitySmithGgx(nDotL, nDotV, alpha);
    return (diffuse + specular) * irradiance * nDotL;
}

// Lit colour of a surface point seen from the camera (linear HDR).
vec3 shadeSurface(SurfacePoint s) {
    vec3 toEye = normalize(frame.cameraPosition.xyz - s.position);
    vec3 color = s.emissive;
    // Ambient: diffuse and a rough Fresnel-weighted specular share of a constant environment.
    vec3 f0 = mix(vec3(0.04), s.baseColor, s.metallic);
    color += frame.ambient.rgb * ((1.0 - s.metallic) * s.baseColor + f0);
    uint count = lightHeader.x;
    for (uint i = 0u; i < count; ++i) {
        GpuLight light = lights[i];
        vec3 toLight = -light.directionType.xyz;
        vec3 irradiance = light.colorIntensity.rgb * light.colorIntensity.a;
        color += brdfDirect(s, toEye, toLight, irradiance);
    }
    return color;
}
