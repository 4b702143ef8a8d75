#version 450 core
// March pass: sphere-traces the SDF scene along each pixel's ray, up to the depth the raster
// pass left, so it never marches behind a mesh, and from the distance the cone pass found free
// for the pixel's tile (passes/cone.frag). A hit is shaded and writes its own depth; a miss
// passes the raster pass's colour, normal, depth and id through unchanged.
#include "common/lighting.glsl"
#include "common/sdf_scene.glsl"
#include "common/sdf_textures.glsl"
#include "common/march_statistics.glsl"
#include "generated/constants.glsl"

in vec3 vRayDirection;
in vec2 vUv;

layout(binding = 0) uniform sampler2D uRasterColor;
layout(binding = 1) uniform sampler2D uRasterNormal;
layout(binding = 2) uniform sampler2D uRasterViewDepth;
layout(binding = 3) uniform usampler2D uRasterObjectId;
layout(binding = 4) uniform sampler2D uRasterDepth;
// x: how far every ray of the tile may skip (0 when the renderer skips the cone pass).
layout(binding = CONE_START_UNIT) uniform sampler2D uConeStart;

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out float outViewDepth;
layout(location = 3) out uint outObjectId;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float rasterViewDepth = texelFetch(uRasterViewDepth, pixel, 0).r;

    // vRayDirection has forward component 1: view depth = t * forwardness of the unit ray.
    float forwardness = 1.0 / length(vRayDirection);
    vec3 rd = vRayDirection * forwardness;
    vec3 ro = frustumOrigin(gl_FragCoord.xy); // the eye, or the pixel's point (orthographic)
    float tMin = max(frame.cameraPosition.w / forwardness,
                     texelFetch(uConeStart, pixel / CONE_TILE_SIZE, 0).x);
    float tMax =
        sdfHitEnd(ro, rd, min(frame.march.y, rasterViewDepth / forwardness), frame.march.z);

    float t;
    int steps = 0;
    if (tMin < tMax &&
        sdfMarch(ro, rd, tMin, tMax, int(frame.march.x), frame.march.z, frame.march.w, t, steps)) {
        vec3 p = ro + rd * t;
        vec3 normal;
        SdfSurface surface =
            sdfSurfaceAndNormal(p, max(frame.march.z * max(t, 1.0), 1e-5), normal);
        SurfacePoint s;
        s.position = p;
        s.normal = normal;
        s.baseColor = surface.baseColor;
        s.metallic = surface.metallic;
        s.roughness = surface.roughness;
        s.emissive = surface.emissive;
        s.occlusion = 1.0;
#ifdef SHADING_SDF_TEXTURES // (generated/shading.glsl: the scene's materials have textures)
        if (materialHasTextures(surface.material))
            applySdfTextures(surface, p, t * forwardness, s);
#endif
        outColor = vec4(shadeSurface(s), 1.0);
        countMarchedFragment(steps, 0); // after the shading: its evaluations count too
        outNormal = vec4(s.normal, float(steps)); // w: march steps (the steps AOV)
        outViewDepth = t * forwardness;
        outObjectId = surface.objectId;
        gl_FragDepth = windowDepth(p);
        return;
    }
    countMarchedFragment(steps, 0);
    outColor = texelFetch(uRasterColor, pixel, 0);
    // Nothing hit here at all: the sky, when the scene has one.
    if (hasSky() && texelFetch(uRasterObjectId, pixel, 0).r == 0u)
        outColor = vec4(skyBackground(rd), 1.0);
    outNormal = vec4(texelFetch(uRasterNormal, pixel, 0).xyz, float(steps));
    outViewDepth = rasterViewDepth;
    outObjectId = texelFetch(uRasterObjectId, pixel, 0).r;
    gl_FragDepth = texelFetch(uRasterDepth, pixel, 0).r;
}
