#version 450 core
// March pass: sphere-traces the SDF scene along each pixel's ray, up to the depth the raster
// pass left, so it never marches behind a mesh. A hit is shaded and writes its own depth; a
// miss passes the raster pass's colour, normal, depth and id through unchanged.
#include "common/lighting.glsl"
#include "common/sdf_scene.glsl"
#include "common/material_textures.glsl"

in vec3 vRayDirection;
in vec2 vUv;

layout(binding = 0) uniform sampler2D uRasterColor;
layout(binding = 1) uniform sampler2D uRasterNormal;
layout(binding = 2) uniform sampler2D uRasterViewDepth;
layout(binding = 3) uniform usampler2D uRasterObjectId;
layout(binding = 4) uniform sampler2D uRasterDepth;

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out float outViewDepth;
layout(location = 3) out uint outObjectId;

// Textures of the hit's material (common/material_textures.glsl). They need the local frame:
// J = d(local point)/d(world point), by forward differences of the surface's local point (exact
// for the affine transforms, close for the bending modifiers). The local normal is J^-T n and a
// bent local normal goes back to world space by J^T (normals are gradients).
void applySdfTextures(SdfSurface surface, vec3 p, float viewDepth, inout SurfacePoint s) {
    float h = 1e-3 * max(1.0, length(p - frame.cameraPosition.xyz) * 0.1);
    mat3 J;
    // One sdfSurface call site in loops that are not unrolled (see SDF_ZERO): the map is
    // compiled once here, not six times.
    for (int axis = SDF_ZERO; axis < 3; ++axis) {
        vec3 e = vec3(0.0);
        e[axis] = h;
        float side = 1.0;
        for (int tries = SDF_ZERO; tries < 2; ++tries) {
            SdfSurface moved = sdfSurface(p + side * e);
            J[axis] = side * (moved.localPoint - surface.localPoint) / h;
            if (moved.objectId == surface.objectId) break;
            side = -side; // across a seam: difference backwards
        }
    }
    float det = determinant(J);
    if (!(abs(det) > 1e-9)) return; // a modifier flattened the frame here: no texture
    vec3 localNormal = normalize(transpose(inverse(J)) * s.normal);
    // A pixel's size at this depth (frustum corners have forward component 1), in local units.
    float pixelWorld = viewDepth * length(frame.frustumCorners[2].xyz -
                                          frame.frustumCorners[0].xyz) / frame.viewport.y;
    // Seen at a grazing angle a pixel stretches over 1 / cos(angle) as much surface; taking
    // the long side (as GPUs without anisotropic filtering do) blurs instead of aliasing.
    float cosView = abs(dot(s.normal, normalize(frame.cameraPosition.xyz - p)));
    float localFootprint = pixelWorld * pow(abs(det), 1.0 / 3.0) / max(cosView, 0.2);
    vec3 bent = localNormal;
    applyMaterialTextures(surface.material, surface.localPoint, localFootprint, bent,
                          s.baseColor, s.roughness);
    if (materialHasNormalTexture(surface.material)) s.normal = normalize(transpose(J) * bent);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float rasterViewDepth = texelFetch(uRasterViewDepth, pixel, 0).r;

    // vRayDirection has forward component 1: view depth = t * forwardness of the unit ray.
    float forwardness = 1.0 / length(vRayDirection);
    vec3 rd = vRayDirection * forwardness;
    vec3 ro = frame.cameraPosition.xyz;
    float tMin = frame.cameraPosition.w / forwardness;
    float tMax = min(frame.march.y, rasterViewDepth / forwardness);

    float t;
    int steps = 0;
    if (tMin < tMax &&
        sdfMarch(ro, rd, tMin, tMax, int(frame.march.x), frame.march.z, t, steps)) {
        vec3 p = ro + rd * t;
        SdfSurface surface = sdfSurface(p);
        vec3 normal = sdfNormal(p, max(frame.march.z * max(t, 1.0), 1e-5));
        SurfacePoint s;
        s.position = p;
        s.normal = normal;
        s.baseColor = surface.baseColor;
        s.metallic = surface.metallic;
        s.roughness = surface.roughness;
        s.emissive = surface.emissive;
        s.occlusion = 1.0;
        if (materialHasTextures(surface.material))
            applySdfTextures(surface, p, t * forwardness, s);
        outColor = vec4(shadeSurface(s), 1.0);
        outNormal = vec4(s.normal, float(steps)); // w: march steps (the steps AOV)
        outViewDepth = t * forwardness;
        outObjectId = surface.objectId;
        gl_FragDepth = windowDepth(p);
        return;
    }
    outColor = texelFetch(uRasterColor, pixel, 0);
    // Nothing hit here at all: the sky, when the scene has one.
    if (hasSky() && texelFetch(uRasterObjectId, pixel, 0).r == 0u)
        outColor = vec4(skyBackground(rd), 1.0);
    outNormal = vec4(texelFetch(uRasterNormal, pixel, 0).xyz, float(steps));
    outViewDepth = rasterViewDepth;
    outObjectId = texelFetch(uRasterObjectId, pixel, 0).r;
    gl_FragDepth = texelFetch(uRasterDepth, pixel, 0).r;
}
