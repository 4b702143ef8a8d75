#version 450 core
// Shell pass: the back faces of a shell's proxy mesh are rasterized (so the camera may be inside
// it); each fragment marches the shell's SDF alone along its camera ray, from the near plane or
// where the ray enters the shell's box, to where it leaves. A miss discards; a hit is shaded with
// the same modules as the march pass and writes the G-buffer and gl_FragDepth, so the shell meets
// meshes and the fullscreen SDF through the depth buffer. Shadows and ambient occlusion see the
// scene's SDF and this shell.
#include "common/shell_scene.glsl"
#define SDF_OCCLUDER_DISTANCE(p) min(sdfDistance(p), shellWorldDistance(p))
#define SDF_OCCLUDERS_EMPTY() false
#define SDF_SURFACE_AT(p) shellSurface(shellObjectPoint(p))
#include "common/lighting.glsl"
#include "common/sdf_textures.glsl"
#include "common/march_statistics.glsl"

in vec3 vWorldPosition;

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out float outViewDepth;
layout(location = 3) out uint outObjectId;

void main() {
    vec3 ro = frame.cameraPosition.xyz;
    vec3 rd = normalize(vWorldPosition - ro);
    if (cameraIsOrthographic()) { // parallel rays, each from its point of the camera's plane
        ro = frustumOrigin(gl_FragCoord.xy);
        rd = frame.cameraForward.xyz;
    }
    float forwardness = dot(rd, frame.cameraForward.xyz);
    float tEnter, tExit;
    if (forwardness <= 0.0 || !shellClipRange(ro, rd, tEnter, tExit)) discard;
    float tMin = max(frame.cameraPosition.w / forwardness, tEnter); // the near plane at least
    float tMax = min(tExit, frame.march.y);
    float t;
    int steps = 0;
    bool hit = tMin < tMax && shellMarch(ro, rd, tMin, tMax, int(frame.march.x), frame.march.z,
                                         frame.march.w, t, steps);
    countMarchedFragment(steps, 1);
    if (!hit) discard;

    vec3 p = ro + rd * t;
    SdfSurface surface = shellSurface(shellObjectPoint(p));
    SurfacePoint s;
    s.position = p;
    s.normal = shellNormal(p, max(frame.march.z * max(t, 1.0), 1e-5));
    s.baseColor = surface.baseColor;
    s.metallic = surface.metallic;
    s.roughness = surface.roughness;
    s.emissive = surface.emissive;
    s.occlusion = 1.0;
#ifdef SHADING_SDF_TEXTURES // (generated/shading.glsl: the scene's materials have textures)
    if (materialHasTextures(surface.material)) applySdfTextures(surface, p, t * forwardness, s);
#endif
    outColor = vec4(shadeSurface(s), 1.0);
    outNormal = vec4(s.normal, float(steps)); // w: march steps (the steps AOV)
    outViewDepth = t * forwardness;
    outObjectId = surface.objectId;
    gl_FragDepth = windowDepth(p);
}
