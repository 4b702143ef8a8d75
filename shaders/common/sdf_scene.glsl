// The SDF scene as every pass sees it: the building blocks, then the scene's map (the virtual
// file "generated/sdf_map.glsl": generated per scene by engine/sdf/glsl_codegen.cpp, or the
// generic interpreter), then normals and sphere tracing on top of it. The map defines
// sdfSceneEmpty(), sdfDistance(p) and sdfSurface(p).
#include "common/frame.glsl"
#include "common/sdf_functions.glsl"
#include "generated/sdf_map.glsl"

#ifndef SDF_HAS_DISTANCE_ALONG
// Maps that know nothing along a ray but the distance (common/sdf_cells.glsl knows more).
float sdfDistanceAlong(vec3 p, vec3 rd, float t, float epsilon, out float advance) {
    advance = 0.0;
    return sdfDistance(p);
}
#endif

#ifndef SDF_HAS_RAY_END
// Maps that hold no grid (common/sdf_cells.glsl has its own): a surface may be anywhere.
float sdfRayEnd(vec3 ro, vec3 rd, float tMax) {
    return tMax;
}
#endif
#ifndef SDF_HAS_HIT_END
float sdfHitEnd(vec3 ro, vec3 rd, float tMax, float epsilon) {
    return sdfRayEnd(ro, rd, tMax);
}
#endif

// The field whose gradient is the normal at a hit: the scene's distance, or the one the map
// names (SDF_SURFACE_FIELD: the nearest shape of a union of shapes, which sdfSurface found;
// common/sdf_cells.glsl). At the hit a union's gradient is its nearest shape's, and one shape
// costs a tap less than the list of the point's cell.
#ifndef SDF_SURFACE_FIELD
#define SDF_SURFACE_FIELD(p) sdfDistance(p)
#endif

// The unit normal at a hit p whose sdfSurface(p) was the last one read: the gradient of
// SDF_SURFACE_FIELD from its values at the tetrahedron's taps p + h * sdfTetrahedronVertex(k)
// (common/sdf_functions.glsl), in a loop that is not unrolled.
vec3 sdfSurfaceNormal(vec3 p, float h) {
    vec4 taps;
    for (int k = SDF_ZERO; k < 4; ++k) taps[k] = SDF_SURFACE_FIELD(p + h * sdfTetrahedronVertex(k));
    return sdfTetrahedronNormal(taps);
}

// The surface at a hit p and its unit normal, h the normal's tap offset. Maps that can read both
// in one pass define their own (SDF_HAS_SURFACE_AND_NORMAL: the interpreter, common/
// sdf_interpreter.glsl); otherwise the surface, then the normal's four taps.
#ifndef SDF_HAS_SURFACE_AND_NORMAL
SdfSurface sdfSurfaceAndNormal(vec3 p, float h, out vec3 normal) {
    SdfSurface surface = sdfSurface(p);
    normal = sdfSurfaceNormal(p, h);
    return surface;
}
#endif

// Over-relaxed sphere tracing (Keinert, Schäfer, Korndörfer, Ganse and Stamminger, "Enhanced
// Sphere Tracing", Eurographics 2014 short papers, section 3.1) on top of sphere tracing (Hart
// 1996, "Sphere tracing"): from t = tMin along the normalized rd, step by relaxation * d. A
// point's distance d is the radius of a ball holding no surface, so a relaxed step is safe
// while the balls of the previous and the new point overlap (previous d + d >= step); when they
// do not, go back to the previous point and take the plain step from there (the paper's
// fallback). The paper then stays at relaxation 1 for the rest of the ray; here it relaxes again
// once the distance grows, the ray moving away from what stopped it (more rays pass near a shape
// than end on it: that measured fewer steps on the benchmark scenes). d is signed and the
// previous one positive, so a step that ended inside a surface fails too. A hit is a point
// reached safely where d < epsilon * max(t, 1). A relaxed step that would pass tMax is taken
// plain, and a step that would pass tLand (tMax, where the ray ends at the farthest distance;
// below tMin: never) lands on it (shorter than the plain step: safe), so whether a ray grazing
// a surface at the farthest distance hits is decided at that one point, not by where its march
// happened to start (the cone pass starts a tile's pixels together: the cut-off edge came out
// in steps of a tile). Gives up after maxSteps evaluations or when t passes tMax. An empty
// program never hits. Where the map knows the ray meets no surface for longer than the distance
// (`advance`, see sdfDistanceAlong in common/sdf_cells.glsl: a cell holding only a plane, or a
// point outside the box that bounds the content), the step goes that far,
// unrelaxed; the previous point's reach is then that length, so the fallback test above still
// holds. engine/sdf/cpu_eval.cpp (sdfCastRay) does the same on the CPU, through the whole
// program (no cells, so no such steps: it stops where the cells' landing is aimed at).
//
// The loop is a macro so that the shell pass (common/shell_scene.glsl, shellMarch) runs the very
// same steps on its own map: DISTANCE_AT_T is the distance at the ray parameter `t`, and may set
// `advance`; the enclosing function has tMin, tMax, tLand, maxSteps, epsilon, relaxation and
// the out values t and steps.
#define SDF_RELAXED_MARCH(DISTANCE_AT_T) \
    float previousT = tMin; \
    float previousDistance = 0.0; /* how far from previousT the ray surely met nothing */ \
    float stepLength = 0.0;       /* from previousT to t */ \
    float omega = relaxation;     /* 1 after a fallback, until the distance grows again */ \
    for (int i = 0; i < maxSteps; ++i) { \
        if (t > tMax) return false; \
        float advance = 0.0; \
        float h = (DISTANCE_AT_T); \
        steps = i + 1; \
        if (stepLength > previousDistance && previousDistance + h < stepLength) { \
            t = previousT + previousDistance; /* back, then the plain step from there */ \
            stepLength = previousDistance; \
            omega = 1.0; \
            continue; \
        } \
        if (h < epsilon * max(t, 1.0)) return true; \
        float reach = max(h, advance); \
        if (reach > previousDistance) omega = relaxation; /* moving away from what stopped it */ \
        float relaxed = advance > h ? reach : omega * h; \
        stepLength = t + relaxed <= tMax ? relaxed : t < tLand ? min(reach, tLand - t) : reach; \
        previousT = t; \
        previousDistance = reach; \
        t += stepLength; \
    } \
    return false;

bool sdfMarch(vec3 ro, vec3 rd, float tMin, float tMax, int maxSteps, float epsilon,
              float relaxation, out float t, out int steps) {
    t = tMin;
    steps = 0;
    if (sdfSceneEmpty()) return false;
    float tLand = tMax >= frame.march.y ? tMax : -1.0; // the farthest distance ends the ray
    SDF_RELAXED_MARCH(sdfDistanceAlong(ro + rd * t, rd, t, epsilon, advance))
}
