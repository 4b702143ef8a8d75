// Shadows and ambient occlusion for every shading pass, so meshes and SDF objects receive the
// same ones:
// - SDF objects cast soft shadows by marching the SDF scene towards the light (Inigo Quilez,
//   "Soft shadows in raymarched SDFs", improved technique that estimates the closest approach
//   between two steps, https://iquilezles.org/articles/rmshadows/);
// - meshes cast shadows through shadow maps rendered by engine/render/shadow_pass.cpp (one
//   layer per view: directional and spot lights one, point lights six), filtered by PCF with
//   hardware 2x2 depth comparison per tap;
// - ambient occlusion is estimated from the SDF along the normal (Inigo Quilez's technique
//   from his raymarching primers: compare the distance found at a few points along the normal
//   with their height above the surface).
#include "common/frame.glsl"
#include "common/scene_buffers.glsl"
#include "common/sdf_scene.glsl"

layout(binding = SHADOW_MAP_UNIT) uniform sampler2DArrayShadow uShadowMaps;

// What casts SDF soft shadows and occludes ambient light: the scene's map, unless the including
// pass defines more (the shell pass adds its shell) before including this file.
#ifndef SDF_OCCLUDER_DISTANCE
#define SDF_OCCLUDER_DISTANCE(p) sdfDistance(p)
#define SDF_OCCLUDERS_EMPTY() sdfSceneEmpty()
#endif

// Visibility of the light from ro along rd, up to tMax, through the SDF objects: 0 = in shadow,
// 1 = lit, in between = penumbra. w is the penumbra width factor (Quilez's 1 / k).
float sdfSoftShadow(vec3 ro, vec3 rd, float tMax, float w) {
    int steps = int(frame.shadow.x);
    if (steps <= 0 || w <= 0.0 || SDF_OCCLUDERS_EMPTY()) return 1.0;
    float result = 1.0;
    float previous = 1e10; // the distance at the previous step
    float t = frame.shadow.y;
    tMax = min(tMax, frame.shadow.z);
    for (int i = 0; i < steps && t < tMax; ++i) {
        float h = SDF_OCCLUDER_DISTANCE(ro + rd * t);
        if (h < 1e-4 * max(t, 1.0)) return 0.0;
        // The closest approach between this sample and the previous one: the spheres of radius
        // `previous` and h around the two samples meet at distance y back along the ray. When
        // they do not meet ahead of the ray's start (y >= h or y >= t: the ray leaves the
        // surface head-on, h doubling each step), that estimate says nothing; the classic
        // h / t bound is used there (Quilez, "Soft shadows", the original estimate), instead of
        // a zero that would print black specks where the light meets the normal.
        float y = h * h / (2.0 * previous);
        if (y < h && y < t) {
            float d = sqrt(h * h - y * y);
            result = min(result, d / (w * (t - y)));
        } else {
            result = min(result, h / (w * t));
        }
        previous = h;
        t += h;
    }
    result = clamp(result, 0.0, 1.0);
    return result * result * (3.0 - 2.0 * result); // smoothstep: a softer edge
}

// Visibility of the light from the mesh shadow maps at world point p with normal n.
float shadowMapVisibility(GpuLight light, vec3 p, vec3 n) {
    int view = int(light.spotShadow.w);
    if (view < 0 || frame.shadowMap.x <= 0.0) return 1.0;
    int type = int(light.directionType.w);
    vec3 fromLight = p - light.positionRange.xyz;
    if (type == LIGHT_POINT) {
        // Six 90-degree views: +X, -X, +Y, -Y, +Z, -Z (matching shadowViewsForLight).
        vec3 a = abs(fromLight);
        if (a.x >= a.y && a.x >= a.z) view += fromLight.x >= 0.0 ? 0 : 1;
        else if (a.y >= a.z) view += fromLight.y >= 0.0 ? 2 : 3;
        else view += fromLight.z >= 0.0 ? 4 : 5;
    }
    GpuShadowView shadowView = shadowViews[view];
    float texel = shadowView.params.x;
    if (shadowView.params.y > 0.5) texel *= length(fromLight);
    // Normal offset: move the lookup off the surface by a few texels so a surface does not
    // shadow itself (acne); the shadow pass adds a slope-scaled depth bias too.
    vec4 clip = shadowView.lightViewProjection * vec4(p + n * texel * frame.shadowMap.z, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    // Beyond the far plane counts as at it: shadowed only by casters drawn in the map.
    float reference = min(ndc.z * 0.5 + 0.5, 1.0);
    int radius = int(frame.shadowMap.y);
    float texelUv = 1.0 / frame.shadowMap.x;
    float lit = 0.0;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x)
            lit += texture(uShadowMaps,
                           vec4(uv + vec2(x, y) * texelUv, shadowView.params.z, reference));
    float taps = float((2 * radius + 1) * (2 * radius + 1));
    return lit / taps;
}

// Visibility of `light` at p (normal n) towards the unit vector toLight, lightDistance away
// (a large number for directional lights): SDF soft shadow times mesh shadow maps.
float lightVisibility(GpuLight light, vec3 p, vec3 n, vec3 toLight, float lightDistance) {
    if (frame.shadow.x <= 0.0) return 1.0;
    float visibility = shadowMapVisibility(light, p, n);
    if (visibility > 0.0 && light.spotShadow.z > 0.0) {
        vec3 ro = p + n * frame.shadow.y;
        visibility *= sdfSoftShadow(ro, toLight, lightDistance, light.spotShadow.z);
    }
    return visibility;
}

// Ambient occlusion at p with normal n from the SDF objects: 1 = open, 0 = fully occluded.
// Samples at heights h_i = distance * i / samples; each contributes (h - d) / h, the share of
// the expected free distance that is missing, with weights falling off 0.85^i.
float sdfAmbientOcclusion(vec3 p, vec3 n) {
    int samples = int(frame.ao.x);
    if (samples <= 0 || SDF_OCCLUDERS_EMPTY()) return 1.0;
    float occlusion = 0.0;
    float weight = 1.0;
    float weights = 0.0;
    for (int i = 1; i <= samples; ++i) {
        float h = frame.ao.y * float(i) / float(samples);
        float d = SDF_OCCLUDER_DISTANCE(p + n * h);
        occlusion += weight * clamp((h - d) / h, 0.0, 1.0);
        weights += weight;
        weight *= 0.85;
    }
    return clamp(1.0 - frame.ao.z * occlusion / weights, 0.0, 1.0);
}
