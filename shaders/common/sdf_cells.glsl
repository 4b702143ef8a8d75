// The SDF map of the Cells strategy: the generic interpreter (common/sdf_interpreter.glsl) run
// on the program of the cell the point is in, out of the cell table that engine/sdf/
// cell_pruning.cpp builds (layout there, SdfCellGrid): blocks of 64 cells, 4 x 4 x 4 per level,
// each cell its list of instruction indices or the block of its 64 children. Points outside the
// grid run the whole program. Expects `sdfPrimitive` declared before it.
#define SDF_CELLS 1

// (Included here, not in the branches below: an include is expanded once, before the
// preprocessor chooses a branch.)
#include "common/sdf_instructions.glsl"

layout(std430, binding = SDF_CELL_BINDING) readonly buffer SdfCellBuffer {
    vec4 sdfCellOrigin; // xyz = the grid cube's corner, w = its edge
    uvec4 sdfCellInfo;  // x = levels (0: no grid), y, z = the whole program's list
    uint sdfCellWords[];
};

#define SDF_PROGRAM_AT(n) sdfCellWords[n]

// The list of the program that runs at p, as sdfCellRange in engine/sdf/cell_pruning.cpp.
void sdfProgramRange(vec3 p, out uint base, out uint count) {
    base = sdfCellInfo.y;
    count = sdfCellInfo.z;
    uint levels = sdfCellInfo.x;
    vec3 u = (p - sdfCellOrigin.xyz) / sdfCellOrigin.w;
    if (levels == 0u || !(all(greaterThanEqual(u, vec3(0.0))) && all(lessThan(u, vec3(1.0)))))
        return;
    uint n = 1u << (2u * levels);
    uvec3 c = min(uvec3(u * float(n)), uvec3(n - 1u));
    uint block = 0u;
    for (uint level = 0u; level < levels; ++level) {
        uvec3 d = (c >> (2u * (levels - 1u - level))) & 3u;
        uint w = 2u * (block * 64u + d.x + 4u * d.y + 16u * d.z);
        uint e = sdfCellWords[w];
        if ((e & 0x80000000u) == 0u) {
            base = e;
            count = sdfCellWords[w + 1u];
            return;
        }
        block = e & 0x7fffffffu;
    }
}

#ifndef SDF_CELLS_LEAN
#include "common/sdf_interpreter.glsl"
#else
// A program whose every part is one shape (the grids: a plain union of shapes, with or without
// its bounding hierarchy) needs no stack: each cell's list is shapes and unions, the whole
// program's box tests and one-shape parts (common/sdf_parts_loop.glsl), both a running minimum.

bool sdfSceneEmpty() { return sdfHeader.x == 0u; }

#define SDF_CELLS_STEP \
    if (n < count) { \
        uint i = SDF_PROGRAM_AT(base + n); \
        uint op = sdfInstructions[i].opcode; \
        if (op == SDF_OPCODE_BOUND_SKIP) { \
            if (sdfBoundDistance(i, p) >= best) n += sdfInstructions[i].kind; \
        } else if (op == SDF_OPCODE_SEED_BEST) { \
            best = min(best, sdfSeedDistance(p, sdfInstructions[i].params[0], \
                                             sdfInstructions[i].params[1], \
                                             sdfInstructions[i].params[2], \
                                             sdfInstructions[i].misc.x)); \
        } else if (sdfIsLeaf(i)) { \
            best = min(best, sdfLeafDistance(i, p)); \
        } \
        ++n; \
    }

float sdfDistance(vec3 p) {
    uint base, count;
    sdfProgramRange(p, base, count);
    float best = SDF_FAR;
    for (uint n = 0u; n < count;) {
        SDF_CELLS_STEP SDF_CELLS_STEP SDF_CELLS_STEP SDF_CELLS_STEP
    }
    return best;
}

// The nearest shape's surface (the first of equal ones, as a union keeps). Once per hit.
SdfSurface sdfSurface(vec3 p) {
    uint base, count;
    sdfProgramRange(p, base, count);
    SdfSurface best = sdfEmptySurface(p);
    for (uint n = 0u; n < count; ++n) {
        uint i = SDF_PROGRAM_AT(base + n);
        uint op = sdfInstructions[i].opcode;
        if (op == SDF_OPCODE_BOUND_SKIP) {
            if (sdfBoundDistance(i, p) >= best.distance) n += sdfInstructions[i].kind;
        } else if (sdfIsLeaf(i)) {
            float d = sdfLeafDistance(i, p);
            if (d < best.distance)
                best = sdfMaterialSurface(d, sdfInstructions[i].objectId,
                                          sdfInstructions[i].material, sdfInstructionPoint(i, p));
        }
    }
    return best;
}
#endif
