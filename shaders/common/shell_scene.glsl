// One shell's SDF (mesh-shell mode, engine/render/include/render/shell_pass.hpp): the map of the shell's
// subtree alone ("generated/shell_map.glsl": shellSceneEmpty, shellDistance, shellSurface), read
// at points in the shell node's own frame (object space) and giving world-unit distances (the
// compiler folds the frame's scale in), and marching it along world-space rays. Rays march only
// inside the shell's box; content that reaches past it (a "bound" on unbounded content) is
// clipped to it.
#include "common/sdf_scene.glsl"
#include "generated/shell_map.glsl"

uniform mat4 uObjectToWorld;
uniform mat4 uWorldToObject;
uniform float uShellDistanceScale; // world units per object unit (a lower bound)
uniform vec3 uShellClipMin;        // object space
uniform vec3 uShellClipMax;
uniform bool uShellClips; // the content reaches past the box: intersect it with the box

vec3 shellObjectPoint(vec3 worldPoint) {
    return (uWorldToObject * vec4(worldPoint, 1.0)).xyz;
}

// Distance to the box, object units.
float shellClipDistance(vec3 q) {
    return sdfBoxDistance(q, 0.5 * (uShellClipMin + uShellClipMax),
                          0.5 * (uShellClipMax - uShellClipMin), 1.0);
}

// The shell's distance at object point q, in world units: its content, intersected with the box
// when it reaches past it. (Bounded content is left alone: the crease of the intersection would
// only disturb the soft-shadow estimate near the box.)
float shellObjectDistance(vec3 q) {
    float d = shellDistance(q);
    return uShellClips ? max(d, shellClipDistance(q) * uShellDistanceScale) : d;
}

// The shell's distance at a world point, in world units (a lower bound for non-uniform scale).
float shellWorldDistance(vec3 worldPoint) {
    return shellObjectDistance(shellObjectPoint(worldPoint));
}

// Where the world ray ro + t rd (rd normalized) is inside the clip box: the slab method (Kay and
// Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986) in object space, where the ray keeps the
// same t because its direction is mapped without normalizing.
bool shellClipRange(vec3 ro, vec3 rd, out float tEnter, out float tExit) {
    vec3 o = shellObjectPoint(ro);
    vec3 d = mat3(uWorldToObject) * rd;
    vec3 inverse = 1.0 / d; // +-inf on axis-parallel rays, which the min/max below handle
    vec3 t0 = (uShellClipMin - o) * inverse;
    vec3 t1 = (uShellClipMax - o) * inverse;
    vec3 near = min(t0, t1);
    vec3 far = max(t0, t1);
    tEnter = max(max(near.x, near.y), near.z);
    tExit = min(min(far.x, far.y), far.z);
    return tEnter <= tExit && tExit > 0.0;
}

// Over-relaxed sphere tracing of the shell with sdfMarch's loop (SDF_RELAXED_MARCH; the CPU's is
// engine/sdf/cpu_eval.cpp, sdfCastRayInFrame), the ray's points taken to object space.
bool shellMarch(vec3 ro, vec3 rd, float tMin, float tMax, int maxSteps, float epsilon,
                float relaxation, out float t, out int steps) {
    t = tMin;
    steps = 0;
    if (shellSceneEmpty()) return false;
    vec3 o = shellObjectPoint(ro);
    vec3 d = mat3(uWorldToObject) * rd;
    float tLand = -1.0; // the shell's box ends the ray, not the farthest distance
    SDF_RELAXED_MARCH(shellObjectDistance(o + d * t))
}

// World-space unit normal at world point p: the tetrahedron gradient (as sdfSurfaceNormal) in
// object space, taken to world space by the transpose of the world-to-object map (normals are
// gradients).
vec3 shellNormal(vec3 p, float h) {
    vec3 q = shellObjectPoint(p);
    float hObject = h / uShellDistanceScale;
    vec3 n = vec3(0.0);
    for (int i = SDF_ZERO; i < 4; ++i) {
        vec3 e = 2.0 * vec3(((i + 3) >> 1) & 1, (i >> 1) & 1, i & 1) - 1.0;
        n += e * shellObjectDistance(q + e * hObject);
    }
    vec3 world = transpose(mat3(uWorldToObject)) * n;
    float len = length(world);
    return len > 0.0 ? world / len : vec3(0.0, 1.0, 0.0);
}
