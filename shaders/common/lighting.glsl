// Shading shared by every pass: the glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification,
// Appendix B "BRDF Implementation"): Lambertian diffuse plus a GGX / Trowbridge-Reitz
// microfacet specular with the height-correlated Smith visibility term and Schlick's Fresnel,
// summed over the scene's lights (directional, point and spot as in glTF KHR_lights_punctual),
// with shadows and ambient occlusion (common/shadows.glsl), sky ambient and fog
// (common/sky.glsl). Shadows and ambient occlusion are compiled only where the frame uses them
// (generated/shading.glsl, render/shading_code.hpp).
#include "common/frame.glsl"
#include "generated/shading.glsl"
#include "common/scene_buffers.glsl"
#include "common/shadows.glsl"
#include "common/sky.glsl"

const float PI = 3.14159265358979;

struct SurfacePoint {
    vec3 position;  // world
    vec3 normal;    // world, normalized, facing the viewer
    vec3 baseColor; // linear
    float metallic;
    float roughness; // perceptual roughness; alpha = roughness^2
    vec3 emissive;
    float occlusion; // material ambient occlusion (glTF occlusion texture), 1 = none
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

// Schlick's approximation. pow() of a negative base is undefined in GLSL (NaN on Mesa), and
// v.h of unit vectors rounds past 1 where the eye and the light lie in one direction from the
// surface: the base is clamped.
vec3 fresnelSchlick(vec3 f0, float vDotH) {
    return f0 + (1.0 - f0) * pow(clamp(1.0 - vDotH, 0.0, 1.0), 5.0);
}

// Radiance reflected towards the eye from light arriving along -lightDir with `irradiance`.
vec3 brdfDirect(SurfacePoint s, vec3 toEye, vec3 toLight, vec3 irradiance) {
    float nDotL = dot(s.normal, toLight);
    if (nDotL <= 0.0) return vec3(0.0);
    float nDotV = max(dot(s.normal, toEye), 1e-4);
    vec3 h = normalize(toLight + toEye);
    float nDotH = clamp(dot(s.normal, h), 0.0, 1.0);
    float vDotH = clamp(dot(toEye, h), 0.0, 1.0);
    float roughness = clamp(s.roughness, 0.03, 1.0);
    float alpha = roughness * roughness;
    vec3 f0 = mix(vec3(0.04), s.baseColor, s.metallic);
    vec3 f = fresnelSchlick(f0, vDotH);
    vec3 diffuse = (1.0 - f) * (1.0 - s.metallic) * s.baseColor / PI;
    vec3 specular = f * distributionGgx(nDotH, alpha) * visibilitySmithGgx(nDotL, nDotV, alpha);
    return (diffuse + specular) * irradiance * nDotL;
}

// KHR_lights_punctual "Range Property": inverse-square falloff with a smooth window that
// reaches 0 at the range: clamp(1 - (d / range)^4, 0, 1)^2 / d^2 (unlimited when range = 0).
float rangeAttenuation(float d, float range) {
    float inverseSquare = 1.0 / max(d * d, 1e-4);
    if (range <= 0.0) return inverseSquare;
    float window = clamp(1.0 - pow(d / range, 4.0), 0.0, 1.0);
    return window * window * inverseSquare;
}

// KHR_lights_punctual "Inner and Outer Cone Angles": saturate(cd * scale + offset)^2 with cd
// the cosine of the angle between the spot's axis and the direction to the point.
float spotAttenuation(GpuLight light, vec3 toLight) {
    float cd = dot(light.directionType.xyz, -toLight);
    float a = clamp(cd * light.spotShadow.x + light.spotShadow.y, 0.0, 1.0);
    return a * a;
}

// Light arriving at s from light i, with its shadows.
vec3 lightContribution(SurfacePoint s, vec3 toEye, GpuLight light) {
    int type = int(light.directionType.w);
    vec3 toLight = -light.directionType.xyz;
    float lightDistance = 1e10;
    float attenuation = 1.0;
    if (type != LIGHT_DIRECTIONAL) {
        vec3 offset = light.positionRange.xyz - s.position;
        lightDistance = length(offset);
        toLight = offset / max(lightDistance, 1e-6);
        attenuation = rangeAttenuation(lightDistance, light.positionRange.w);
        if (type == LIGHT_SPOT) attenuation *= spotAttenuation(light, toLight);
    }
    if (attenuation <= 0.0 || dot(s.normal, toLight) <= 0.0) return vec3(0.0);
    vec3 irradiance = light.colorIntensity.rgb * light.colorIntensity.a * attenuation;
#ifdef SHADING_SHADOWS
    float visibility = lightVisibility(light, s.position, s.normal, toLight, lightDistance);
    if (visibility <= 0.0) return vec3(0.0);
#else
    float visibility = 1.0;
#endif
    return brdfDirect(s, toEye, toLight, irradiance * visibility);
}

// Lit colour of a surface point seen from the camera (linear HDR), fogged.
vec3 shadeSurface(SurfacePoint s) {
    vec3 toEye = toViewer(s.position);
    vec3 color = s.emissive;
#ifdef SHADING_AMBIENT_OCCLUSION
    float occlusion = s.occlusion * sdfAmbientOcclusion(s.position, s.normal);
#else
    float occlusion = s.occlusion;
#endif
    vec3 f0 = mix(vec3(0.04), s.baseColor, s.metallic);
    if (hasSky()) {
        // Diffuse: the sky averaged around the normal; specular: the sky along the reflection,
        // blurred by the roughness, weighted by Schlick's Fresnel with the roughness-aware
        // maximum of Fdez-Aguera ("A Multiple-Scattering Microfacet Model for Real-Time Image
        // Based Lighting", 2019).
        float nDotV = clamp(dot(s.normal, toEye), 0.0, 1.0);
        vec3 fresnel = f0 + (max(vec3(1.0 - s.roughness), f0) - f0) * pow(1.0 - nDotV, 5.0);
        vec3 reflected = reflect(-toEye, s.normal);
        color += occlusion * ((1.0 - fresnel) * (1.0 - s.metallic) * s.baseColor *
                                  skyDiffuse(s.normal) +
                              fresnel * skySpecular(reflected, s.roughness));
    } else {
        // Ambient: diffuse and a rough Fresnel-weighted specular share of a constant environment.
        color += occlusion * frame.ambient.rgb * ((1.0 - s.metallic) * s.baseColor + f0);
    }
    uint count = lightHeader.x;
    for (uint i = 0u; i < count; ++i) color += lightContribution(s, toEye, lights[i]);
    return applyFog(color, viewerDistance(s.position));
}
