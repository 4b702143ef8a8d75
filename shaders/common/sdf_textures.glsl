// Material textures on SDF surfaces (triplanar, common/material_textures.glsl), shared by the
// march pass and the shell pass. The surface function is SDF_SURFACE_AT(p) (world point), the
// scene's sdfSurface unless the including pass defines another before including this file.
#include "common/lighting.glsl"
#include "common/material_textures.glsl"
#include "common/sdf_scene.glsl"

#ifndef SDF_SURFACE_AT
#define SDF_SURFACE_AT(p) sdfSurface(p)
#endif

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
            SdfSurface moved = SDF_SURFACE_AT(p + side * e);
            J[axis] = side * (moved.localPoint - surface.localPoint) / h;
            if (moved.objectId == surface.objectId) break;
            side = -side; // across a seam: difference backwards
        }
    }
    float det = determinant(J);
    if (!(abs(det) > 1e-9)) return; // a modifier flattened the frame here: no texture
    vec3 localNormal = normalize(transpose(inverse(J)) * s.normal);
    // A pixel's size at this depth (frustum corners have forward component 1), in local units;
    // orthographic: the same at every depth.
    float pixelWorld = cameraIsOrthographic()
                           ? 2.0 * length(frame.orthoUp.xyz) / frame.viewport.y
                           : viewDepth * length(frame.frustumCorners[2].xyz -
                                                frame.frustumCorners[0].xyz) / frame.viewport.y;
    // Seen at a grazing angle a pixel stretches over 1 / cos(angle) as much surface; taking
    // the long side (as GPUs without anisotropic filtering do) blurs instead of aliasing.
    float cosView = abs(dot(s.normal, toViewer(p)));
    float localFootprint = pixelWorld * pow(abs(det), 1.0 / 3.0) / max(cosView, 0.2);
    vec3 bent = localNormal;
    applyMaterialTextures(surface.material, surface.localPoint, localFootprint, bent,
                          s.baseColor, s.roughness);
    if (materialHasNormalTexture(surface.material)) s.normal = normalize(transpose(J) * bent);
}
