// The SDF map of a program made of the bounding hierarchy's instructions only: box tests,
// seeds, and parts that are one shape (a shape or profile followed by its Accumulate), which is
// what a large union of shapes compiles to (engine/sdf/compiler.cpp). A lean interpreter of those
// instructions alone, without the value and point stacks and the other opcodes of the generic
// one (common/sdf_interpreter.glsl); engine/sdf/glsl_codegen.cpp picks it when the program fits.
// Its text depends on the primitive kinds used only. Expects `sdfPrimitive` declared before it.
#include "common/sdf_instructions.glsl"

bool sdfSceneEmpty() { return sdfHeader.x == 0u; }

// One instruction (or a shape and its Accumulate) of sdfDistance, repeated to unroll the loop:
// llvmpipe ends a shader invocation's loops after a budget of iterations shared by every loop
// (see common/sdf_interpreter.glsl).
#define SDF_PARTS_STEP \
    if (i < count) { \
        SdfInstructionData data = sdfInstructionData(i); /* read once: SdfInstructionData */ \
        uvec4 head = data.head; /* opcode, kind, material, id */ \
        uint op = head.x; \
        if (op == SDF_OPCODE_BOUND_SKIP) { \
            if (sdfBoundDistanceOf(data, p) >= best) i += head.y; \
            i += 1u; \
        } else if (op == SDF_OPCODE_SEED_BEST) { \
            best = min(best, sdfSeedDistanceOf(data, p)); \
            i += 1u; \
        } else { \
            float d = sdfLeafDistanceOf(data, p); \
            if (d < best) { \
                best = d; \
                nearest = i; \
            } \
            i += 2u; \
        } \
    }

// The part nearest to the point sdfDistance was last asked about (its instruction index; at
// first the part nearest the camera, which the renderer finds on the CPU, where every
// pixel's first march step is). Consecutive points of a march, a normal or a shadow ray are close, so it is usually
// the nearest part again: evaluated first, it makes `best` tight from the start and the box
// tests skip nearly every other part, where the program's fixed order alone lets every part
// nearer than the ones before it through. The value is the same: `best` is always some part's
// distance (or a seed, an upper bound of one), and a box is skipped only when nothing in it is
// nearer than `best`.
uint sdfNearestPart = 0xffffffffu;

float sdfDistance(vec3 p) {
    uint count = sdfHeader.x;
    float best = SDF_FAR;
    uint nearest = sdfNearestPart;
    if (nearest == 0xffffffffu && frame.viewport.z < float(count)) nearest = uint(frame.viewport.z);
    if (nearest < count && sdfIsLeaf(nearest)) best = sdfLeafDistance(nearest, p);
    for (uint i = 0u; i < count;) {
        SDF_PARTS_STEP SDF_PARTS_STEP SDF_PARTS_STEP SDF_PARTS_STEP
    }
    sdfNearestPart = nearest;
    return best;
}

// The nearest part's surface (no seeds: `best` must be a part's surface). Once per hit.
SdfSurface sdfSurface(vec3 p) {
    uint count = sdfHeader.x;
    SdfSurface best = sdfEmptySurface(p);
    for (uint i = 0u; i < count;) {
        uvec4 head = sdfInstructionHead(i); // opcode, kind, material, id
        uint op = head.x;
        if (op == SDF_OPCODE_BOUND_SKIP) {
            if (sdfBoundDistance(i, p) >= best.distance) i += head.y;
            i += 1u;
        } else if (op == SDF_OPCODE_SEED_BEST) {
            i += 1u;
        } else {
            float d = sdfLeafDistance(i, p);
            if (d < best.distance)
                best = sdfMaterialSurface(d, head.w, head.z, sdfInstructionPoint(i, p));
            i += 2u;
        }
    }
    return best;
}
