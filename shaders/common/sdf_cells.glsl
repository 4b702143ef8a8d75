// The SDF map of the Cells strategy: the generic interpreter (common/sdf_interpreter.glsl) run
// on the program of the cell the point is in, out of the cell table that engine/sdf/
// cell_pruning.cpp builds (layout there, SdfCellGrid): blocks of 64 cells, 4 x 4 x 4 per level,
// each cell its list of instruction indices or the block of its 64 children. Points outside the
// grid run the outside list (the whole program's unbounded operands but the planes below, such
// as an infinite repetition) and the distance to the floor of the rest (sdfCellDistance). No
// list holds a bounding hierarchy (but
// for programs whose tree cannot be read: SDF_HAS_BOUNDS). The planes of the root's chain of
// unions are in no list: each point unites the list's value with theirs, one dot product each
// (SdfCellGrid::planes). Expects `sdfPrimitive` declared before it.
#define SDF_CELLS 1

// (Included here, not in the branches below: an include is expanded once, before the
// preprocessor chooses a branch.)
#include "common/sdf_instructions.glsl"

// The header (engine/render/gpu_layout.hpp, GpuSdfCellHeader): a uniform block over the
// buffer's start, which llvmpipe reads once for all pixels (a storage buffer: once per pixel).
layout(std140, binding = SDF_CELL_HEADER_BINDING) uniform SdfCellHeader {
    vec4 sdfCellOrigin; // xyz = the grid cube's corner, w = its edge
    uvec4 sdfCellInfo;  // x = levels (0: no grid), y, z = the outside list (the whole program's
                        // when there is no grid), w = 1 when every surface lies inside the cube
    vec4 sdfCellFloorMin; // a floor (sdfCellDistance): its box, w = drop
    vec4 sdfCellFloorMax; // w: 1 the whole program's, + 2 the outside list's, 0 none
    // The grid's planes: fields dot(xyz, p) + w (SDF_FAR where there is none), and their
    // instructions (0xffffffffu where there is none), the top bit set where the plane's surface
    // is kept over a list's at an equal distance (SdfCellPlane::leads: a union keeps the first
    // of equal operands). The loops over them read the first SDF_CELLS_PLANES (engine/sdf/
    // glsl_codegen.cpp: the program's plane instructions, at most SDF_CELL_PLANES; undefined
    // where there is none): llvmpipe runs every iteration of a loop of constant length.
    vec4 sdfCellPlaneFields[SDF_CELL_PLANES];
    uvec4 sdfCellPlaneInstructions;
    vec4 sdfCellHitEndMin; // a box that holds every point whose field is at most w (0: none)
    vec4 sdfCellHitEndMax;
}; // then the words (SdfCellGrid::words), read through sdfCellTexels below
// The header's size in texels of two words (engine/render/gpu_layout.hpp, GpuSdfCellHeader).
#define SDF_CELL_HEADER_TEXELS (2u * uint(7 + SDF_CELL_PLANES))

// The same buffer as pairs of words (a buffer texture over it, engine/render/gpu_scene.cpp),
// read at indices that differ between pixels: a cell's two words in one fetch, where llvmpipe
// loads storage-buffer words one at a time (see sdfProgramTexels in common/sdf_functions.glsl).
// Word n is in texel SDF_CELL_HEADER_TEXELS + n / 2 (after the header).
layout(binding = SDF_CELL_TEXEL_UNIT) uniform usamplerBuffer sdfCellTexels;

uvec2 sdfCellPair(uint k) {
    return texelFetch(sdfCellTexels, int(SDF_CELL_HEADER_TEXELS + k)).xy;
}
uint sdfCellWord(uint n) {
    uvec2 pair = sdfCellPair(n >> 1u);
    return (n & 1u) == 0u ? pair.x : pair.y;
}

// Where the line ro + s rd enters (x) and leaves (y) the box [lo, hi]: the slab test (Kay and
// Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986). The ray misses the box where
// y < max(x, 0).
vec2 sdfBoxSpan(vec3 lo, vec3 hi, vec3 ro, vec3 rd) {
    vec3 d = mix(rd, vec3(1e-20), lessThan(abs(rd), vec3(1e-20)));
    vec3 t0 = (lo - ro) / d;
    vec3 t1 = (hi - ro) / d;
    vec3 near = min(t0, t1), far = max(t0, t1);
    return vec2(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z));
}

// How far along the ray ro + t rd a surface can be: where the ray leaves the grid's cube when
// every surface lies inside it (nothing is outside to meet: 0 when the ray misses the cube), else
// tMax. The march stops there instead of running the whole program outside the grid until
// tMax.
#define SDF_HAS_RAY_END 1
float sdfRayEnd(vec3 ro, vec3 rd, float tMax) {
    if (sdfCellInfo.x == 0u || sdfCellInfo.w == 0u) return tMax;
    vec2 span =
        sdfBoxSpan(sdfCellOrigin.xyz, sdfCellOrigin.xyz + vec3(sdfCellOrigin.w), ro, rd);
    return span.y < max(span.x, 0.0) ? 0.0 : min(tMax, span.y);
}

// How far along the ray ro + t rd the march can hit a surface: sdfRayEnd, and where the ray
// leaves the header's hit-end box (the scene's bounds at a field level, engine/render/
// gpu_scene.cpp: setHitEnd) when the hit threshold epsilon * max(t, 1) stays within that level
// up to there. A hit needs the field below the threshold, so it lies in the box; a ray past the
// content ends there instead of crossing the grid's empty space (0 when it misses the box).
#define SDF_HAS_HIT_END 1
float sdfHitEnd(vec3 ro, vec3 rd, float tMax, float epsilon) {
    float end = sdfRayEnd(ro, rd, tMax);
    float level = sdfCellHitEndMin.w;
    if (level <= 0.0 || epsilon * max(end, 1.0) > level) return end;
    vec2 span = sdfBoxSpan(sdfCellHitEndMin.xyz, sdfCellHitEndMax.xyz, ro, rd);
    return span.y < max(span.x, 0.0) ? 0.0 : min(end, span.y);
}

// The list of the program that runs at p, as sdfCellRange in engine/sdf/cell_pruning.cpp. The
// descent is written out level by level (at most SDF_CELL_MAX_LEVELS): a loop's iterations
// would come out of llvmpipe's budget shared by every loop of the shader (see
// common/sdf_interpreter.glsl), and llvmpipe runs each level's code whether or not a loop ends
// early anyway.
#define SDF_CELL_LEVEL(level) \
    if (block != 0xffffffffu && level < levels) { \
        uint shift = 2u * (levels - 1u - level); \
        uvec3 d = (c >> shift) & 3u; \
        uvec2 e = sdfCellPair(block * 64u + d.x + 4u * d.y + 16u * d.z); \
        if ((e.x & 0x80000000u) == 0u) { \
            base = e.x; \
            count = e.y; \
            block = 0xffffffffu; \
            leafShift = shift; \
        } else { \
            block = e.x & 0x7fffffffu; \
        } \
    }
// Also the cell itself: `cell` its lowest corner (xyz) and edge (w; 0 outside the grid), and
// `affine` its kSdfCellAffine flag (its program is one plane, engine/sdf/cell_pruning.hpp).
void sdfProgramCell(vec3 p, out uint base, out uint count, out bool affine, out vec4 cell) {
    base = sdfCellInfo.y;
    count = sdfCellInfo.z;
    affine = false;
    cell = vec4(0.0);
    uint levels = sdfCellInfo.x;
    vec3 u = (p - sdfCellOrigin.xyz) / sdfCellOrigin.w;
    if (levels == 0u || !(all(greaterThanEqual(u, vec3(0.0))) && all(lessThan(u, vec3(1.0)))))
        return;
    uint n = 1u << (2u * levels);
    uvec3 c = min(uvec3(u * float(n)), uvec3(n - 1u));
    uint block = 0u;
    uint leafShift = 0u;
#if SDF_CELL_MAX_LEVELS != 6
#error "sdfProgramCell descends 6 levels: write out SDF_CELL_MAX_LEVELS"
#endif
    SDF_CELL_LEVEL(0u) SDF_CELL_LEVEL(1u) SDF_CELL_LEVEL(2u)
    SDF_CELL_LEVEL(3u) SDF_CELL_LEVEL(4u) SDF_CELL_LEVEL(5u)
    if (block != 0xffffffffu) return; // (no leaf: not a grid the pruning writes)
    affine = (count & SDF_CELL_AFFINE) != 0u;
    count &= ~SDF_CELL_AFFINE;
    float edge = sdfCellOrigin.w / float(n >> leafShift);
    cell = vec4(sdfCellOrigin.xyz + vec3(c >> leafShift) * edge, edge);
}
void sdfProgramRange(vec3 p, out uint base, out uint count) {
    bool affine;
    vec4 cell;
    sdfProgramCell(p, base, count, affine, cell);
}

// The distance at p of the cell `cell` (sdfProgramCell) whose list gives `distance`. A floor
// (engine/sdf/cell_pruning.hpp, SdfFieldFloor: at every point outside its box a field is at
// least the distance to the box less the drop) counts twice:
// - Outside the grid (cell.w = 0) the list leaves out the operands the floor stands for
//   (SdfCellGrid::outsideFloor, w = 2 or 3), so the distance is the least of the two: a lower
//   bound, equal to the field wherever the list is nearer (every surface a march can meet out
//   there), and the box's distance, not a bounding hierarchy's program, where the content is.
// - A far cell's constant is the least the field can be anywhere in the cell, so a coarse cell
//   beside the content gives its far side no more than its near side. The whole program's
//   floor (w = 1 or 3) is a lower bound at p itself; the larger of the two is the distance
//   there. A cone (passes/cone.frag) then passes the empty space beside the content (it stopped
//   on the constants), and soft shadows and AO read less darkness into it. Without a plane in
//   the scene every affine cell is a constant (and a scene with a plane has no such floor).
// A plane's field counts as an evaluation of its primitive (`rmsc bench`'s evaluations a pixel).
#ifdef SDF_COUNT_EVALUATIONS
#define SDF_COUNT_PLANE(k, n) \
    if (sdfCellPlaneInstructions[k] != 0xffffffffu) sdfEvaluations += (n)
#else
#define SDF_COUNT_PLANE(k, n)
#endif

// Then the grid's planes are united with it (the nearest one's gradient in `planeGradient`).
float sdfCellDistance(float distance, vec3 p, bool affine, vec4 cell, out vec3 planeGradient) {
    bool outside = cell.w == 0.0;
    float uses = sdfCellFloorMax.w;
    if (outside ? uses >= 2.0 : affine && (uses == 1.0 || uses == 3.0)) {
        vec3 away = max(max(sdfCellFloorMin.xyz - p, p - sdfCellFloorMax.xyz), vec3(0.0));
        float floorDistance = length(away) - sdfCellFloorMin.w;
        distance = outside ? min(distance, floorDistance) : max(distance, floorDistance);
    }
    planeGradient = vec3(0.0);
#ifdef SDF_CELLS_PLANES
    for (int k = 0; k < SDF_CELLS_PLANES; ++k) {
        vec4 field = sdfCellPlaneFields[k];
        float d = dot(field.xyz, p) + field.w;
        SDF_COUNT_PLANE(k, 1u);
        planeGradient = d < distance ? field.xyz : planeGradient;
        distance = min(distance, d);
    }
#endif
    return distance;
}
float sdfCellDistance(float distance, vec3 p, bool affine, vec4 cell) {
    vec3 planeGradient;
    return sdfCellDistance(distance, p, affine, cell, planeGradient);
}

// Whether a plane (its instruction word `i`, nearer by d) takes the place of the surface at
// `distance`, which a plane gave or not (`fromPlane`): the first of equal ones stays, the
// planes in their order, before the list where they lead it (SdfCellPlane::leads).
bool sdfCellPlaneWins(uint i, float d, float distance, bool fromPlane) {
    return d < distance || ((i & 0x80000000u) != 0u && !fromPlane && d == distance);
}

// `surface` (a list's, at p) united with the grid's planes' surfaces; with `withTaps`, `taps`
// (its values at the normal's taps t0 to t3) too.
SdfSurface sdfCellPlanesSurface(SdfSurface surface, vec3 p, bool withTaps, vec3 t0, vec3 t1,
                                vec3 t2, vec3 t3, inout vec4 taps) {
#ifdef SDF_CELLS_PLANES
    bool fromPlane = false;
    for (int k = 0; k < SDF_CELLS_PLANES; ++k) {
        vec4 field = sdfCellPlaneFields[k];
        uint i = sdfCellPlaneInstructions[k];
        if (i == 0xffffffffu) continue;
        float d = dot(field.xyz, p) + field.w;
        SDF_COUNT_PLANE(k, withTaps ? 5u : 1u);
        if (withTaps)
            taps = min(taps, vec4(dot(field.xyz, t0), dot(field.xyz, t1), dot(field.xyz, t2),
                                  dot(field.xyz, t3)) + field.w);
        if (sdfCellPlaneWins(i, d, surface.distance, fromPlane)) {
            i &= 0x7fffffffu;
            uvec4 head = sdfInstructionHead(i); // opcode, kind, material, id
            surface = sdfMaterialSurface(d, head.w, head.z, sdfInstructionPoint(i, p));
            fromPlane = true;
        }
    }
#endif
    return surface;
}

#ifndef SDF_CELLS_LEAN
// The lists are postfix in entries of two words, a texel each (SdfListReading::PostfixPairs in
// engine/sdf/include/sdf/program.hpp): an instruction and the combine after it. `base` is in
// words, and even.
#define SDF_LIST_PAIRS 1
#define SDF_LIST_ENTRY(base, n) sdfCellPair(((base) >> 1u) + (n))
#include "common/sdf_interpreter.glsl"
#else
#define SDF_PROGRAM_AT(n) sdfCellWord(n) // (one word an entry)
// A program whose every part is one shape (the grids: a plain union of shapes, with or without
// its bounding hierarchy; sdfIsLeastOfShapes in engine/sdf/program_form.cpp) needs no stack:
// each cell's list and the outside list are shapes, a running minimum. (A list with unions
// still reads right: they do nothing here.)

bool sdfSceneEmpty() { return sdfHeader.x == 0u; }

// One instruction per loop iteration: a cell's list is a few shapes, and llvmpipe would run
// unrolled instructions past its end for nothing (masked). The lists hold no unions
// (SdfListReading::LeastOfShapes, engine/sdf/cell_pruning.cpp): a running minimum is their
// value, so an iteration is a shape.

// Also the numbers of the list's last instruction (a cell's plane, sdfDistanceAlong).
float sdfListDistanceLast(vec3 p, uint base, uint count, out SdfInstructionData last) {
    float best = SDF_FAR;
    for (uint n = 0u; n < count; ++n) {
        uint i = SDF_PROGRAM_AT(base + n);
        SdfInstructionData data = sdfInstructionData(i); // read once: SdfInstructionData
        last = data;
        uvec4 head = data.head; // opcode, kind, material, id
        uint op = head.x;
        if (op == SDF_OPCODE_SHAPE || op == SDF_OPCODE_PROFILE)
            best = min(best, sdfLeafDistanceOf(data, p));
    }
    return best;
}
float sdfListDistance(vec3 p, uint base, uint count) {
    SdfInstructionData last;
    return sdfListDistanceLast(p, base, count, last);
}

float sdfDistance(vec3 p) {
    uint base, count;
    bool affine;
    vec4 cell;
    sdfProgramCell(p, base, count, affine, cell);
    return sdfCellDistance(sdfListDistance(p, base, count), p, affine, cell);
}

// The instruction of the shape sdfSurface last found nearest, and its field: the normal at the
// hit is its gradient (sdfSurfaceNormal, common/sdf_scene.glsl).
uint sdfNearestShape = 0u;
#define SDF_SURFACE_FIELD(p) sdfLeafDistance(sdfNearestShape, p)

// The nearest shape's surface (the first of equal ones, as a union keeps), the grid's planes'
// included. Once per hit.
SdfSurface sdfSurface(vec3 p) {
    uint base, count;
    sdfProgramRange(p, base, count);
    SdfSurface best = sdfEmptySurface(p);
    for (uint n = 0u; n < count; ++n) {
        uint i = SDF_PROGRAM_AT(base + n);
        uvec4 head = sdfInstructionHead(i); // opcode, kind, material, id
        uint op = head.x;
        if (op == SDF_OPCODE_SHAPE || op == SDF_OPCODE_PROFILE) {
            float d = sdfLeafDistance(i, p);
            if (d < best.distance) {
                best = sdfMaterialSurface(d, head.w, head.z, sdfInstructionPoint(i, p));
                sdfNearestShape = i;
            }
        }
    }
#ifdef SDF_CELLS_PLANES
    bool fromPlane = false;
    for (int k = 0; k < SDF_CELLS_PLANES; ++k) {
        uint i = sdfCellPlaneInstructions[k];
        if (i == 0xffffffffu) continue;
        vec4 field = sdfCellPlaneFields[k];
        float d = dot(field.xyz, p) + field.w;
        SDF_COUNT_PLANE(k, 1u);
        if (sdfCellPlaneWins(i, d, best.distance, fromPlane)) {
            i &= 0x7fffffffu;
            uvec4 head = sdfInstructionHead(i);
            best = sdfMaterialSurface(d, head.w, head.z, sdfInstructionPoint(i, p));
            sdfNearestShape = i;
            fromPlane = true;
        }
    }
#endif
    return best;
}
#endif

#ifdef SDF_CELLS_PLANES // (engine/sdf/glsl_codegen.cpp: the scene has a plane)
// The rate at which a plane instruction's field (its numbers `plane`) changes along the unit
// direction rd: sdPlane (common/sdf_primitives.glsl) of the frame's point, dot(q, normal) /
// |normal| - offset, times the distance scale, where q changes by the frame's linear part
// applied to rd.
float sdfPlaneSlope(SdfInstructionData plane, vec3 rd) {
    vec3 dq = vec3(dot(plane.r0.xyz, rd), dot(plane.r1.xyz, rd), dot(plane.r2.xyz, rd));
    vec3 normal = plane.a0.xyz;
    return dot(dq, normal) / max(length(normal), 1e-6) * plane.misc.x;
}

// How far along rd a march stepping by a plane's field (d at t, changing by `slope` per unit
// of rd) stops on it: at its first point under the hit threshold epsilon * max(t, 1), which lies
// within a step's decrease of it; a step of length h lowers the field by |slope| h, so the point
// where the field is (1 - |slope| / 2) times the threshold, halfway. d + slope s = landing
// max(t + s, 1), solved for s. The threshold grows by epsilon a unit of t, so it may catch up with
// a plane the ray does not go towards (0 <= slope < landing: a ray level with a floor); SDF_FAR
// where it never does. (Where the threshold is still constant, t + s < 1, such a plane gives 0:
// no more is known than the distance.)
float sdfPlaneLanding(float d, float slope, float t, float epsilon) {
    float landing = (1.0 + 0.5 * slope) * epsilon;
    if (landing - slope <= 0.0) return SDF_FAR;
    float s = (d - landing * t) / (landing - slope);
    if (t + s < 1.0) s = slope < 0.0 ? (d - landing) / -slope : 0.0;
    return max(s, 0.0);
}
#endif

// How far along the unit direction rd from p = ro + t rd the content (every surface but the
// grid's planes) stays beyond the march's hit threshold: 0 where that is not known, SDF_FAR where
// the ray never comes near it. The header's floor stands for the content when it is the whole
// program's, or the outside list's with that list empty (then, the planes aside, the floor's
// operands are all there is): the content's field is at least distance(y, box) - drop at every
// point y, so above a threshold m wherever y is outside the box grown by drop + m. The threshold,
// epsilon * max(t', 1), grows along the ray. The ray's points before the grown box are at most
// F + sqrt(3) m along it, F = t + |p - centre| + the box's half diagonal + sqrt(3) drop (the
// grown box's corners are that much farther out), so m = 2 epsilon max(F, 1) is above the
// threshold there: epsilon (F + sqrt(3) m) <= epsilon max(F, 1) (1 + 2 sqrt(3) epsilon) <= m for
// epsilon <= 1 / (2 sqrt(3)); a larger epsilon (up to 1) takes no such step.
float sdfContentEntry(vec3 p, vec3 rd, float t, float epsilon) {
    float uses = sdfCellFloorMax.w;
    if (uses == 0.0 || (uses == 2.0 && sdfCellInfo.z != 0u) || epsilon > 0.25) return 0.0;
    vec3 lo = sdfCellFloorMin.xyz, hi = sdfCellFloorMax.xyz;
    float drop = max(sdfCellFloorMin.w, 0.0);
    float far = t + length(p - 0.5 * (lo + hi)) + 0.5 * length(hi - lo) + 1.7320508 * drop;
    float grow = drop + 2.0 * epsilon * max(far, 1.0);
    vec2 span = sdfBoxSpan(lo - vec3(grow), hi + vec3(grow), p, rd);
    return span.y < max(span.x, 0.0) ? SDF_FAR : max(span.x, 0.0);
}

// sdfDistance at p = ro + t rd, and `advance`: how far along the unit direction rd from p the
// ray surely meets no surface (0 when no more is known than the distance). Two things tell:
// - In a cell whose program is one plane (kSdfCellAffine: its list's, or with an empty list the
//   grid's plane nearest at p, the others being above it in the cell) the only surface is where
//   that plane's field is zero, and the field changes at a constant rate along the ray: the ray
//   may go to the cell's far side (sdfBoxSpan), or, when the plane is nearer, to where a march
//   would stop on it (sdfPlaneLanding). The floor's depth then does not change
//   from one cell to the next. A ray grazing a floor crosses such a cell in one step where sphere
//   tracing would take many (common/sdf_scene.glsl).
// - Outside the box that bounds the content, grown by the hit threshold (sdfContentEntry), the
//   ray may go to that box, or to the first of the grid's planes it would stop on: a ray over a
//   field of shapes on a floor comes down to them in a step (where it crossed a cell a step,
//   each a fraction of the way), and one past the content lands on the floor beyond it.
// Scenes without a plane leave the planes out: their cost in every step (llvmpipe runs a branch
// whether or not a pixel takes it) would buy nothing.
#define SDF_HAS_DISTANCE_ALONG 1
float sdfDistanceAlong(vec3 p, vec3 rd, float t, float epsilon, out float advance) {
    uint base, count;
    bool affine;
    vec4 cell;
    sdfProgramCell(p, base, count, affine, cell);
    SdfInstructionData last; // an affine cell's list is its plane: the numbers the list read
    vec3 planeGradient;
    float d = sdfCellDistance(sdfListDistanceLast(p, base, count, last), p, affine, cell,
                              planeGradient);
    advance = 0.0;
#ifdef SDF_CELLS_PLANES
    if (affine) {
        float exit = max(sdfBoxSpan(cell.xyz, cell.xyz + vec3(cell.w), p, rd).y, 0.0);
        float slope = count == 0u ? dot(planeGradient, rd) : sdfPlaneSlope(last, rd);
        advance = min(exit, sdfPlaneLanding(d, slope, t, epsilon));
    }
#endif
    float entry = sdfContentEntry(p, rd, t, epsilon);
    if (entry > 0.0) {
        float landing = SDF_FAR;
#ifdef SDF_CELLS_PLANES
        for (int k = 0; k < SDF_CELLS_PLANES; ++k) {
            vec4 field = sdfCellPlaneFields[k];
            float planeLanding =
                sdfPlaneLanding(dot(field.xyz, p) + field.w, dot(field.xyz, rd), t, epsilon);
            bool used = field.w < SDF_FAR; // (none: a zero gradient and SDF_FAR)
            landing = used ? min(landing, planeLanding) : landing;
        }
#endif
        advance = max(advance, min(entry, landing));
    }
    return d;
}
