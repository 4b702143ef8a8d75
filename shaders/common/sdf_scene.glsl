// The SDF scene interpreter: runs the postfix program compiled by engine/sdf/compiler.cpp from
// the SDF program buffer, giving the scene distance (for marching), the surface material and
// object id at a hit, normals and sphere tracing. Mirrored exactly by engine/sdf/cpu_eval.cpp.
#include "common/scene_buffers.glsl"
#include "common/sdf_primitives.glsl"
#include "generated/primitives.glsl"

// Must equal kSdfMaxStack in engine/sdf/program.hpp; the compiler refuses deeper programs.
#define SDF_MAX_STACK 24

// SdfOpcode (engine/sdf/program.hpp).
#define SDF_OPCODE_SHAPE 0u
#define SDF_OPCODE_COMBINE 1u

// SdfOp (engine/scene/scene.hpp).
#define SDF_OP_UNION 0u
#define SDF_OP_SUBTRACTION 1u
#define SDF_OP_INTERSECTION 2u
#define SDF_OP_SMOOTH_UNION 3u
#define SDF_OP_SMOOTH_SUBTRACTION 4u
#define SDF_OP_SMOOTH_INTERSECTION 5u

// Distance reported by an empty program: nothing anywhere.
#define SDF_FAR 1e10

// Mirrors GpuSdfInstruction (std430, 112 bytes).
struct SdfInstruction {
    uint opcode;         // SDF_OPCODE_*
    uint kind;           // primitive id for a shape, SDF_OP_* for a combine
    uint material;       // shape: index into materials[]
    uint objectId;       // shape: object id
    vec4 params[3];      // shape: primitive parameters; combine: params[0].x = smoothness k
    vec4 worldToLocal[3];// shape: rows of the affine world-to-local matrix
    vec4 misc;           // shape: x = distance scale
};

layout(std430, binding = 0) readonly buffer SdfProgramBuffer {
    uvec4 sdfHeader; // x = instruction count, y = stack depth (GpuSdfHeader)
    SdfInstruction sdfInstructions[];
};

// Distance of the shape instruction i at world point p: the primitive evaluated at the local
// point, scaled back to world units.
float sdfShapeDistance(uint i, vec3 p) {
    vec4 p4 = vec4(p, 1.0);
    vec3 q = vec3(dot(sdfInstructions[i].worldToLocal[0], p4),
                  dot(sdfInstructions[i].worldToLocal[1], p4),
                  dot(sdfInstructions[i].worldToLocal[2], p4));
    return sdfPrimitive(sdfInstructions[i].kind, q, sdfInstructions[i].params[0],
                        sdfInstructions[i].params[1], sdfInstructions[i].params[2]) *
           sdfInstructions[i].misc.x;
}

// Combines a (below) and b (top of the stack) with operation op and smoothness k. weightA is
// how much of a's material the result carries: 1 or 0 for the hard operations (the side that
// won the min/max; subtraction keeps a), the blend factor h for the smooth ones.
// Formulas: Inigo Quilez, "Smooth minimum" (polynomial quadratic),
// https://iquilezles.org/articles/smin/ and https://iquilezles.org/articles/distfunctions/.
float sdfCombine(uint op, float a, float b, float k, out float weightA) {
    if (op == SDF_OP_UNION) {
        weightA = a <= b ? 1.0 : 0.0;
        return min(a, b);
    }
    if (op == SDF_OP_SUBTRACTION) {
        weightA = 1.0;
        return max(a, -b);
    }
    if (op == SDF_OP_INTERSECTION) {
        weightA = a >= b ? 1.0 : 0.0;
        return max(a, b);
    }
    if (op == SDF_OP_SMOOTH_UNION) {
        float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
        weightA = h;
        return mix(b, a, h) - k * h * (1.0 - h);
    }
    if (op == SDF_OP_SMOOTH_SUBTRACTION) {
        float h = clamp(0.5 - 0.5 * (b + a) / k, 0.0, 1.0);
        weightA = 1.0;
        return mix(a, -b, h) + k * h * (1.0 - h);
    }
    // SDF_OP_SMOOTH_INTERSECTION
    float h = clamp(0.5 - 0.5 * (b - a) / k, 0.0, 1.0);
    weightA = h;
    return mix(b, a, h) + k * h * (1.0 - h);
}

// The scene distance at p (world units; negative inside). Used by the march loop.
float sdfDistance(vec3 p) {
    uint count = sdfHeader.x;
    if (count == 0u) return SDF_FAR;
    float stack[SDF_MAX_STACK];
    int top = 0; // number of entries on the stack
    for (uint i = 0u; i < count; ++i) {
        if (sdfInstructions[i].opcode == SDF_OPCODE_SHAPE) {
            stack[top] = sdfShapeDistance(i, p);
            ++top;
        } else {
            float weightA;
            float b = stack[top - 1];
            float a = stack[top - 2];
            stack[top - 2] = sdfCombine(sdfInstructions[i].kind, a, b,
                                        sdfInstructions[i].params[0].x, weightA);
            --top;
        }
    }
    return stack[0];
}

// Surface properties at a point: distance, dominant object and blended material.
struct SdfSurface {
    float distance;
    uint objectId;
    vec3 baseColor;
    float metallic;
    float roughness;
    vec3 emissive;
};

SdfSurface sdfShapeSurface(uint i, vec3 p) {
    SdfSurface s;
    s.distance = sdfShapeDistance(i, p);
    s.objectId = sdfInstructions[i].objectId;
    uint m = sdfInstructions[i].material;
    if (m < uint(materials.length())) {
        s.baseColor = materials[m].baseColorMetallic.rgb;
        s.metallic = materials[m].baseColorMetallic.a;
        s.emissive = materials[m].emissiveRoughness.rgb;
        s.roughness = materials[m].emissiveRoughness.a;
    } else { // the defaults of Material (engine/scene/scene.hpp)
        s.baseColor = vec3(0.8);
        s.metallic = 0.0;
        s.emissive = vec3(0.0);
        s.roughness = 0.5;
    }
    return s;
}

// The same program as sdfDistance, carrying the material and object id: blended with the
// factor of the distances, the id of the side with weight >= 0.5. Evaluated once per hit.
SdfSurface sdfSurface(vec3 p) {
    uint count = sdfHeader.x;
    SdfSurface stack[SDF_MAX_STACK];
    int top = 0;
    for (uint i = 0u; i < count; ++i) {
        if (sdfInstructions[i].opcode == SDF_OPCODE_SHAPE) {
            stack[top] = sdfShapeSurface(i, p);
            ++top;
        } else {
            SdfSurface b = stack[top - 1];
            SdfSurface a = stack[top - 2];
            float w;
            float d = sdfCombine(sdfInstructions[i].kind, a.distance, b.distance,
                                 sdfInstructions[i].params[0].x, w);
            SdfSurface r = w >= 0.5 ? a : b; // the dominant side; exact for the hard ops
            if (w > 0.0 && w < 1.0) {
                r.baseColor = mix(b.baseColor, a.baseColor, w);
                r.metallic = mix(b.metallic, a.metallic, w);
                r.roughness = mix(b.roughness, a.roughness, w);
                r.emissive = mix(b.emissive, a.emissive, w);
            }
            r.distance = d;
            stack[top - 2] = r;
            --top;
        }
    }
    if (count == 0u) {
        SdfSurface none;
        none.distance = SDF_FAR;
        none.objectId = 0u;
        none.baseColor = vec3(0.8);
        none.metallic = 0.0;
        none.roughness = 0.5;
        none.emissive = vec3(0.0);
        return none;
    }
    return stack[0];
}

// Normalized gradient of the scene distance by the tetrahedron technique: 4 evaluations at
// p + h * (+-1, +-1, +-1) (Inigo Quilez, "Normals for an SDF",
// https://iquilezles.org/articles/normalsSDF/).
vec3 sdfNormal(vec3 p, float h) {
    const vec2 k = vec2(1.0, -1.0);
    vec3 n = k.xyy * sdfDistance(p + k.xyy * h) + k.yyx * sdfDistance(p + k.yyx * h) +
             k.yxy * sdfDistance(p + k.yxy * h) + k.xxx * sdfDistance(p + k.xxx * h);
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
    if (sdfHeader.x == 0u) return false;
    for (int i = 0; i < maxSteps; ++i) {
        if (t > tMax) return false;
        float d = sdfDistance(ro + rd * t);
        steps = i + 1;
        if (d < epsilon * max(t, 1.0)) return true;
        t += d;
    }
    return false;
}
