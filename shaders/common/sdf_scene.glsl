// The SDF scene as every pass sees it: the building blocks, then the scene's map (the virtual
// file "generated/sdf_map.glsl": generated per scene by engine/sdf/glsl_codegen.cpp, or the
// generic interpreter), then normals and sphere tracing on top of it. The map defines
// sdfSceneEmpty(), sdfDistance(p) and sdfSurface(p).
#include "common/frame.glsl"
#include "common/sdf_functions.glsl"
#include "generated/sdf_map.glsl"

// A zero the shader compiler cannot see through (the frame's step budget is at least 1). Loops
// that start at SDF_ZERO are neither unrolled nor is their body inlined once per iteration, so
// the scene's map is compiled once per loop instead of once per tap: the "ZERO" idiom from
// Inigo Quilez's Shadertoy work, see "Normals for an SDF",
// https://iquilezles.org/articles/normalsSDF/ (section "Non-inlining the normal").
#define SDF_ZERO min(int(frame.march.x), 0)

// Normalized gradient of the scene distance by the tetrahedron technique: 4 evaluations at
// p + h * (+-1, +-1, +-1) (Inigo Quilez, "Normals for an SDF", the same article), in a loop that
// is not unrolled.
vec3 sdfNormal(vec3 p, float h) {
    vec3 n = vec3(0.0);
    for (int i = SDF_ZERO; i < 4; ++i) {
        vec3 e = 2.0 * vec3(((i + 3) >> 1) & 1, (i >> 1) & 1, i & 1) - 1.0;
        n += e * sdfDistance(p + e * h);
    }
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 1.0, 0.0);
}

// Sphere tracing (Hart 1996, "Sphere tracing"): from t = tMin along the normalized rd, step by
// the distance; a hit when the distance falls below epsilon * max(t, 1). Gives up after
// maxSteps steps or when t passes tMax. An empty program never hits.
bool sdfMarch(vec3 ro, vec3 rd, float tMin, float tMax, int maxSteps, float epsilon, out float t,
              out int steps) {
    t = tMin;
    steps = 0;
    if (sdfSceneEmpty()) return false;
    for (int i = 0; i < maxSteps; ++i) {
        if (t > tMax) return false;
        float d = sdfDistance(ro + rd * t);
        steps = i + 1;
        if (d < epsilon * max(t, 1.0)) return true;
        t += d;
    }
    return false;
}
