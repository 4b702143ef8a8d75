#version 450 core
// Cone pass: the low-resolution pre-pass of the march pass. One fragment per tile of
// CONE_TILE_SIZE^2 pixels (texel (x, y) for the pixels (x, y) * CONE_TILE_SIZE and up) marches a
// cone holding every ray of the tile and writes how far all of them may skip: passes/march.frag
// starts each pixel's march there, not at the near plane.
// The idea is cone marching (one march for a bundle of neighbouring rays; see e.g. Nabil
// Mansour, "Cone Marching in Three.js", https://nabilmansour.com/articles/cone-marching-in-three-js);
// the step and the bound below are derived here.
//
// The bound. Let a be the unit axis of the cone and u the unit ray of any pixel of the tile,
// both from the camera; the points at distance s along them are s * |u - a| <= s * k apart,
// k the largest chord over the tile (the angle to a is quasi-convex over the image plane, so
// the largest is at a corner of the tile). The scene distance d is 1-Lipschitz, so
//     d(ray at s) >= d(axis at s) - k s,
// and the march pass counts a hit where d < epsilon * max(s, 1) (common/sdf_scene.glsl). With
//     g(s) = d(axis at s) - k s - epsilon * max(s, 1),
// every pixel ray stays farther than its hit threshold on [s, s + g(s) / (1 + k + epsilon)]
// (the three terms change by at most 1, k and epsilon per unit of s), so that is the step: no
// pixel's march meets a surface before the distance written here, and each one finds the same
// first surface as a march from the near plane.
//
// An orthographic camera's rays are parallel: the tile's rays fill a cylinder about the ray
// through its centre, each at most r (the tile's half diagonal in world units) from it at the
// same depth s, so d(ray at s) >= d(axis at s) - r, and the same argument with k = 0 and
//     g(s) = d(axis at s) - r - epsilon * max(s, 1)
// gives the step g(s) / (1 + epsilon). Both run the one loop below (r is 0 for a perspective
// camera), so the scene's map is compiled into this shader once.
#include "common/sdf_scene.glsl"
#include "generated/constants.glsl"
#include "common/march_statistics.glsl"

layout(location = 0) out vec2 outCone; // x = distance every ray of the tile may skip, y = steps

void main() {
    vec2 tileCorner = floor(gl_FragCoord.xy) * float(CONE_TILE_SIZE);
    vec3 axis = normalize(frustumRay(tileCorner + 0.5 * float(CONE_TILE_SIZE)));
    float k = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
        vec2 offset = vec2(corner & 1, corner >> 1) * float(CONE_TILE_SIZE);
        k = max(k, length(normalize(frustumRay(tileCorner + offset)) - axis));
    }
    vec3 ro = frame.cameraPosition.xyz;
    float r = 0.0; // the cylinder's radius (orthographic)
    if (cameraIsOrthographic()) {
        ro = frustumOrigin(tileCorner + 0.5 * float(CONE_TILE_SIZE));
        vec2 pixel = 2.0 * vec2(length(frame.orthoRight.xyz), length(frame.orthoUp.xyz)) /
                     frame.viewport.xy;
        r = 0.5 * float(CONE_TILE_SIZE) * length(pixel);
    }
    float epsilon = frame.march.z;
    // The near plane: no pixel's march starts nearer (its start is near / forwardness).
    float s = frame.cameraPosition.w;
    int steps = 0;
    if (!sdfSceneEmpty()) {
        // No farther than where the axis leaves the cells' grid, when nothing is outside it:
        // stopping early only leaves a nearer start, and the pixels' marches end there too.
        float sEnd = sdfRayEnd(ro, axis, frame.march.y);
        for (int i = SDF_ZERO; i < int(frame.march.x) && s < sEnd; ++i) {
            float g = sdfDistance(ro + axis * s) - k * s - epsilon * max(s, 1.0) - r;
            steps = i + 1;
            // The cone touches a surface (or nearly: a quarter of its radius left), so the
            // pixels take over.
            if (g < 0.25 * k * s + 0.25 * r) break;
            s += g / (1.0 + k + epsilon);
        }
    }
    countEvaluations();
    outCone = vec2(s, float(steps));
}
