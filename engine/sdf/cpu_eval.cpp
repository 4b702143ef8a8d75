// The CPU evaluator: the interpreter of shaders/common/sdf_scene.glsl written again with GLM,
// statement for statement (same stack, same formulas, same march rule), so CPU results predict
// what the shader computes. The single formulas are in sdf_functions.cpp.
#include "sdf/cpu_eval.hpp"

#include "sdf/modifiers.hpp"
#include "sdf/sdf_functions.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace rmsc {
namespace {

// Distance of a shape instruction at world point p: the primitive at the local point, scaled
// back to world units (sdfShapeDistance in the shader).
float shapeDistance(const GpuSdfInstruction& instruction, glm::vec3 p) {
    const glm::vec4 p4(p, 1.0f);
    const glm::vec3 q(glm::dot(instruction.worldToLocal[0], p4),
                      glm::dot(instruction.worldToLocal[1], p4),
                      glm::dot(instruction.worldToLocal[2], p4));
    const PrimitiveParams params = {
        instruction.params[0].x, instruction.params[0].y, instruction.params[0].z,
        instruction.params[0].w, instruction.params[1].x, instruction.params[1].y,
        instruction.params[1].z, instruction.params[1].w, instruction.params[2].x,
        instruction.params[2].y, instruction.params[2].z, instruction.params[2].w};
    const PrimitiveSpec& spec = primitiveSpec(PrimitiveId(instruction.kind));
    return spec.distance(q, params.data()) * instruction.misc.x;
}

// Distance of a profile instruction at world point p: the 2D profile solid at the local point,
// scaled back to world units.
float profileDistance(const GpuSdfInstruction& instruction, const std::vector<glm::vec4>& data,
                      glm::vec3 p) {
    const glm::vec4 p4(p, 1.0f);
    const glm::vec3 q(glm::dot(instruction.worldToLocal[0], p4),
                      glm::dot(instruction.worldToLocal[1], p4),
                      glm::dot(instruction.worldToLocal[2], p4));
    return sdfProfile(SdfProfileType(instruction.kind), q, instruction.params, data) *
           instruction.misc.x;
}

// Distance of a shape or profile instruction at the current point.
float leafDistance(const SdfProgram& program, const GpuSdfInstruction& instruction, glm::vec3 p) {
    return instruction.opcode == std::uint32_t(SdfOpcode::Profile)
               ? profileDistance(instruction, program.data, p)
               : shapeDistance(instruction, p);
}

// A distance modifier at the current point (sdfDistanceModifier in the shader).
float distanceModifier(const GpuSdfInstruction& instruction, float d, glm::vec3 p) {
    return modifierOfKind(ModifierStage::Distance, instruction.kind)
        .changeDistance(d, p, instruction.params);
}

bool isLeaf(const GpuSdfInstruction& instruction) {
    return instruction.opcode == std::uint32_t(SdfOpcode::Shape) ||
           instruction.opcode == std::uint32_t(SdfOpcode::Profile);
}

// The point instructions (sdfPointStep in the shader): true if `instruction` was one.
bool pointStep(const GpuSdfInstruction& instruction, glm::vec3& p,
               std::array<glm::vec3, kSdfMaxPointStack>& saved, int& savedTop) {
    switch (SdfOpcode(instruction.opcode)) {
    case SdfOpcode::PushPoint: {
        assert(savedTop < kSdfMaxPointStack);
        saved[std::size_t(savedTop++)] = p;
        const glm::vec4 p4(p, 1.0f);
        p = glm::vec3(glm::dot(instruction.worldToLocal[0], p4),
                      glm::dot(instruction.worldToLocal[1], p4),
                      glm::dot(instruction.worldToLocal[2], p4));
        return true;
    }
    case SdfOpcode::PointModifier:
        p = modifierOfKind(ModifierStage::Point, instruction.kind).movePoint(p, instruction.params);
        return true;
    case SdfOpcode::PopPoint:
        assert(savedTop > 0);
        p = saved[std::size_t(--savedTop)];
        return true;
    default:
        return false;
    }
}

SdfSurface shapeSurface(const SdfProgram& program, const GpuSdfInstruction& instruction,
                        std::span<const Material> materials, glm::vec3 p) {
    SdfSurface s; // defaults = Material's defaults, used for an index out of range
    s.distance = leafDistance(program, instruction, p);
    s.objectId = instruction.objectId;
    s.material = instruction.material;
    const glm::vec4 p4(p, 1.0f);
    s.localPoint = glm::vec3(glm::dot(instruction.worldToLocal[0], p4),
                             glm::dot(instruction.worldToLocal[1], p4),
                             glm::dot(instruction.worldToLocal[2], p4));
    if (instruction.material < materials.size()) {
        const Material& m = materials[instruction.material];
        s.baseColor = m.baseColor;
        s.metallic = m.metallic;
        s.emissive = m.emissive;
        s.roughness = m.roughness;
    }
    return s;
}

// The distance from p to a BoundSkip instruction's box, in world units (sdfBoxDistance in the
// shader; Inigo Quilez, "Distance functions": sdBox).
float boundDistance(const GpuSdfInstruction& instruction, glm::vec3 p) {
    const glm::vec3 q =
        glm::abs(p - glm::vec3(instruction.params[0])) - glm::vec3(instruction.params[1]);
    return (glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f)) *
           instruction.misc.x;
}

// SeedBest: the nearer of the two boxes' farthest points (sdfSeedDistance in the shader).
float seedDistance(const GpuSdfInstruction& in, glm::vec3 p) {
    const glm::vec3 ca(in.params[0]), ha(in.params[0].w, in.params[1].x, in.params[1].y);
    const glm::vec3 cb(in.params[1].z, in.params[1].w, in.params[2].x), hb(in.params[2]);
    return std::min(glm::length(glm::abs(p - ca) + ha), glm::length(glm::abs(p - cb) + hb)) *
           in.misc.x;
}

} // namespace

std::uint32_t sdfNearestLeaf(const SdfProgram& program, glm::vec3 p) {
    std::uint32_t nearest = ~0u;
    float best = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < program.instructions.size(); ++i) {
        const GpuSdfInstruction& instruction = program.instructions[i];
        if (!isLeaf(instruction)) continue;
        const float d = leafDistance(program, instruction, p);
        if (d < best) {
            best = d;
            nearest = std::uint32_t(i);
        }
    }
    return nearest;
}

namespace {

// The instructions a run reads, in order: the program's own (Whole) or those an index list
// names (Ordered: a per-cell program, sdf/cell_pruning.hpp). A BoundSkip skips list positions.
struct WholeProgram {
    const std::vector<GpuSdfInstruction>& code;
    static constexpr bool leastOfShapes = false;
    std::size_t size() const { return code.size(); }
    const GpuSdfInstruction& operator[](std::size_t n) const { return code[n]; }
};
struct OrderedProgram {
    std::span<const GpuSdfInstruction> code;
    std::span<const std::uint32_t> order;
    bool leastOfShapes = false; // SdfListReading::LeastOfShapes
    std::size_t size() const { return order.size(); }
    const GpuSdfInstruction& operator[](std::size_t n) const { return code[order[n]]; }
};

template <class Code>
float distanceOf(const SdfProgram& program, const Code& code, glm::vec3 p, int* evaluations) {
    if (code.size() == 0) return kSdfFar;
    std::array<float, kSdfMaxStack> stack{};
    int top = 0; // number of entries on the stack
    std::array<glm::vec3, kSdfMaxPointStack> saved{};
    int savedTop = 0;
    float best = kSdfFar; // what Accumulate unites into
    for (std::size_t i = 0; i < code.size(); ++i) {
        const GpuSdfInstruction& instruction = code[i];
        if (instruction.opcode == std::uint32_t(SdfOpcode::BoundSkip)) {
            // A box no nearer than the best so far cannot hold a nearer part; one that is
            // nearer bounds the result from above by its farthest point, which lets its
            // siblings be skipped sooner (the value stays exact: see SdfCompileOptions).
            if (boundDistance(instruction, p) >= best) i += instruction.kind;
        } else if (instruction.opcode == std::uint32_t(SdfOpcode::SeedBest)) {
            best = std::min(best, seedDistance(instruction, p));
        } else if (code.leastOfShapes) { // shapes into `best`; unions and Accumulate: nothing
            if (!isLeaf(instruction)) continue;
            if (evaluations) ++*evaluations;
            best = std::min(best, leafDistance(program, instruction, p));
        } else if (instruction.opcode == std::uint32_t(SdfOpcode::Accumulate)) {
            assert(top >= 1);
            best = std::min(best, stack[--top]);
        } else if (isLeaf(instruction)) {
            assert(top < kSdfMaxStack);
            if (evaluations) ++*evaluations;
            stack[top] = leafDistance(program, instruction, p);
            ++top;
        } else if (pointStep(instruction, p, saved, savedTop)) {
        } else if (instruction.opcode == std::uint32_t(SdfOpcode::DistanceModifier)) {
            assert(top >= 1);
            stack[top - 1] = distanceModifier(instruction, stack[top - 1], p);
        } else {
            assert(top >= 2);
            float weightA = 0.0f;
            const float b = stack[top - 1];
            const float a = stack[top - 2];
            stack[top - 2] =
                sdfCombine(SdfOp(instruction.kind), a, b, instruction.params[0], weightA);
            --top;
        }
    }
    return top == 0 ? best : stack[0];
}

template <class Code>
SdfSurface surfaceOf(const SdfProgram& program, const Code& code,
                     std::span<const Material> materials, glm::vec3 p) {
    if (code.size() == 0) {
        SdfSurface none;
        none.distance = kSdfFar;
        return none;
    }
    std::array<SdfSurface, kSdfMaxStack> stack{};
    int top = 0;
    std::array<glm::vec3, kSdfMaxPointStack> saved{};
    int savedTop = 0;
    SdfSurface best; // what Accumulate unites into: the nearest so far
    best.distance = kSdfFar;
    for (std::size_t i = 0; i < code.size(); ++i) {
        const GpuSdfInstruction& instruction = code[i];
        if (instruction.opcode == std::uint32_t(SdfOpcode::BoundSkip)) {
            if (boundDistance(instruction, p) >= best.distance) i += instruction.kind;
        } else if (instruction.opcode == std::uint32_t(SdfOpcode::SeedBest)) {
            // Surfaces are not seeded: `best` must be a part's surface.
        } else if (code.leastOfShapes) { // the first of equal ones, as a union keeps
            if (!isLeaf(instruction)) continue;
            const SdfSurface s = shapeSurface(program, instruction, materials, p);
            if (s.distance < best.distance) best = s;
        } else if (instruction.opcode == std::uint32_t(SdfOpcode::Accumulate)) {
            assert(top >= 1);
            --top;
            if (stack[top].distance < best.distance) best = stack[top];
        } else if (isLeaf(instruction)) {
            assert(top < kSdfMaxStack);
            stack[top] = shapeSurface(program, instruction, materials, p);
            ++top;
        } else if (pointStep(instruction, p, saved, savedTop)) {
        } else if (instruction.opcode == std::uint32_t(SdfOpcode::DistanceModifier)) {
            assert(top >= 1);
            stack[top - 1].distance = distanceModifier(instruction, stack[top - 1].distance, p);
        } else {
            assert(top >= 2);
            const SdfSurface b = stack[top - 1];
            const SdfSurface a = stack[top - 2];
            float w = 0.0f;
            const float d = sdfCombine(SdfOp(instruction.kind), a.distance, b.distance,
                                       instruction.params[0], w);
            SdfSurface r = w >= 0.5f ? a : b; // the dominant side; exact for the hard ops
            if (w > 0.0f && w < 1.0f) {
                r.baseColor = glm::mix(b.baseColor, a.baseColor, w);
                r.metallic = glm::mix(b.metallic, a.metallic, w);
                r.roughness = glm::mix(b.roughness, a.roughness, w);
                r.emissive = glm::mix(b.emissive, a.emissive, w);
            }
            r.distance = d;
            stack[top - 2] = r;
            --top;
        }
    }
    return top == 0 ? best : stack[0];
}

} // namespace

float sdfDistance(const SdfProgram& program, glm::vec3 p, int* evaluations) {
    return distanceOf(program, WholeProgram{program.instructions}, p, evaluations);
}

SdfSurface sdfSurface(const SdfProgram& program, std::span<const Material> materials, glm::vec3 p) {
    return surfaceOf(program, WholeProgram{program.instructions}, materials, p);
}

namespace {
// The instructions a list in pairs runs, in order (sdfListProgram: its combines as its entries
// hold them, as the shader reads them).
const std::vector<GpuSdfInstruction>& pairedProgram(std::span<const GpuSdfInstruction> code,
                                                    std::span<const std::uint32_t> words) {
    thread_local std::vector<GpuSdfInstruction> run;
    run.clear();
    sdfListProgram(code, words, SdfListReading::PostfixPairs, run);
    return run;
}
} // namespace

float sdfDistanceOrdered(const SdfProgram& program, std::span<const GpuSdfInstruction> code,
                         std::span<const std::uint32_t> order, glm::vec3 p, int* evaluations,
                         SdfListReading reading) {
    if (reading == SdfListReading::PostfixPairs)
        return distanceOf(program, WholeProgram{pairedProgram(code, order)}, p, evaluations);
    return distanceOf(program,
                      OrderedProgram{code, order, reading == SdfListReading::LeastOfShapes}, p,
                      evaluations);
}

SdfSurface sdfSurfaceOrdered(const SdfProgram& program, std::span<const GpuSdfInstruction> code,
                             std::span<const std::uint32_t> order,
                             std::span<const Material> materials, glm::vec3 p,
                             SdfListReading reading) {
    if (reading == SdfListReading::PostfixPairs)
        return surfaceOf(program, WholeProgram{pairedProgram(code, order)}, materials, p);
    return surfaceOf(program, OrderedProgram{code, order, reading == SdfListReading::LeastOfShapes},
                     materials, p);
}

float sdfLeafDistance(const SdfProgram& program, const GpuSdfInstruction& instruction,
                      glm::vec3 p) {
    return leafDistance(program, instruction, p);
}

// Tetrahedron technique (Inigo Quilez, "Normals for an SDF",
// https://iquilezles.org/articles/normalsSDF/): 4 evaluations at p + h * (+-1, +-1, +-1).
glm::vec3 sdfNormal(const SdfProgram& program, glm::vec3 p, float h) {
    const glm::vec3 xyy(1.0f, -1.0f, -1.0f);
    const glm::vec3 yyx(-1.0f, -1.0f, 1.0f);
    const glm::vec3 yxy(-1.0f, 1.0f, -1.0f);
    const glm::vec3 xxx(1.0f, 1.0f, 1.0f);
    const glm::vec3 n =
        xyy * sdfDistance(program, p + xyy * h) + yyx * sdfDistance(program, p + yyx * h) +
        yxy * sdfDistance(program, p + yxy * h) + xxx * sdfDistance(program, p + xxx * h);
    const float len = glm::length(n);
    return len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

namespace {

// Over-relaxed sphere tracing (Keinert, Schäfer, Korndörfer, Ganse and Stamminger, "Enhanced
// Sphere Tracing", Eurographics 2014 short papers, section 3.1) on top of sphere tracing (Hart
// 1996, "Sphere tracing"), as sdfMarch in shaders/common/sdf_scene.glsl: `distanceAt(t)` is
// the distance at the ray's point t. Steps by relaxation * d. A point's distance d is the
// radius of a ball that holds no surface, so a relaxed step is safe while the balls of the
// previous point and of the new one overlap (previous d + d >= step). When they do not, the
// march goes back to the previous point and takes the plain step from there (the paper's
// fallback). The paper then stays at relaxation 1 for the rest of the ray; here it relaxes
// again once the distance grows, the ray moving away from what stopped it (more rays pass
// near a shape than end on it: that measured fewer steps on the benchmark scenes). d is signed
// and the previous one positive, so a step that ended inside a surface fails too. Hits are
// only taken at points reached safely. A relaxed step that would pass tMax is taken plain, so
// no surface before tMax is skipped, and one that would pass tLand (tMax where the ray ends at
// the farthest distance; below tMin: never) lands on it, so whether a ray grazing a surface at
// the farthest distance hits does not depend on where its march started (the march pass's
// SDF_RELAXED_MARCH does the same).
struct MarchResult {
    bool hit = false;
    float t = 0.0f;
    int steps = 0; // evaluations, hit or not
};

template <typename DistanceAt>
MarchResult relaxedMarch(DistanceAt distanceAt, int maxSteps, float epsilon, float relaxation,
                         float tMin, float tMax, float tLand) {
    float t = tMin;
    float previousT = tMin;
    float previousDistance = 0.0f; // at previousT
    float stepLength = 0.0f;       // from previousT to t
    float omega = relaxation;      // 1 after a fallback, until the distance grows again
    for (int i = 0; i < maxSteps; ++i) {
        if (t > tMax) return {false, t, i};
        const float d = distanceAt(t);
        if (stepLength > previousDistance && previousDistance + d < stepLength) {
            t = previousT + previousDistance; // back, then the plain step from there
            stepLength = previousDistance;
            omega = 1.0f;
            continue;
        }
        if (d < epsilon * std::max(t, 1.0f)) return {true, t, i + 1};
        if (d > previousDistance) omega = relaxation; // moving away from what stopped it
        stepLength = t + omega * d <= tMax ? omega * d : t < tLand ? std::min(d, tLand - t) : d;
        previousT = t;
        previousDistance = d;
        t += stepLength;
    }
    return {false, t, maxSteps};
}

// The march of sdfCastRay along the normalized direction.
MarchResult castRay(const SdfProgram& program, const RenderSettings& settings, glm::vec3 origin,
                    glm::vec3 direction, float tMin, float tMax, float relaxation) {
    if (program.instructions.empty()) return {};
    const float len = glm::length(direction);
    if (!(len > 0.0f)) return {};
    const glm::vec3 rd = direction / len;
    // As the march pass: a ray that ends at the farthest distance lands on it.
    const float tLand = tMax >= settings.maxDistance ? tMax : -1.0f;
    return relaxedMarch([&](float t) { return sdfDistance(program, origin + rd * t); },
                        settings.maxSteps, settings.surfaceEpsilon, relaxation, tMin, tMax, tLand);
}

} // namespace

std::optional<SdfHit> sdfCastRay(const SdfProgram& program, const RenderSettings& settings,
                                 glm::vec3 origin, glm::vec3 direction, float tMin, float tMax,
                                 float relaxation) {
    const MarchResult march = castRay(program, settings, origin, direction, tMin, tMax, relaxation);
    if (!march.hit) return std::nullopt;
    return SdfHit{march.t, origin + glm::normalize(direction) * march.t, march.steps};
}

int sdfMarchSteps(const SdfProgram& program, const RenderSettings& settings, glm::vec3 origin,
                  glm::vec3 direction, float tMin, float tMax, float relaxation) {
    return castRay(program, settings, origin, direction, tMin, tMax, relaxation).steps;
}

SdfConeMarch sdfMarchCone(const SdfProgram& program, const RenderSettings& settings,
                          glm::vec3 origin, glm::vec3 axis, float chord, float start,
                          float radius) {
    SdfConeMarch cone{start, 0};
    if (program.instructions.empty()) return cone;
    const float epsilon = settings.surfaceEpsilon;
    float& s = cone.distance;
    for (int i = 0; i < settings.maxSteps && s < settings.maxDistance; ++i) {
        const float g = sdfDistance(program, origin + axis * s) - chord * s -
                        epsilon * std::max(s, 1.0f) - radius;
        cone.steps = i + 1;
        if (g < 0.25f * chord * s + 0.25f * radius) break;
        s += g / (1.0f + chord + epsilon);
    }
    return cone;
}

std::optional<SdfHit> sdfCastRayInFrame(const SdfProgram& program, const glm::mat4& worldToFrame,
                                        const RenderSettings& settings, glm::vec3 origin,
                                        glm::vec3 direction, float tMin, float tMax,
                                        float relaxation) {
    if (program.instructions.empty()) return std::nullopt;
    const float len = glm::length(direction);
    if (!(len > 0.0f)) return std::nullopt;
    const glm::vec3 rd = direction / len;
    // The frame's ray keeps the world ray's t: its direction is mapped, not normalized.
    const glm::vec3 o = glm::vec3(worldToFrame * glm::vec4(origin, 1.0f));
    const glm::vec3 d = glm::mat3(worldToFrame) * rd;
    const MarchResult march =
        relaxedMarch([&](float t) { return sdfDistance(program, o + d * t); }, settings.maxSteps,
                     settings.surfaceEpsilon, relaxation, tMin, tMax, -1.0f);
    if (!march.hit) return std::nullopt;
    return SdfHit{march.t, origin + rd * march.t, march.steps};
}

} // namespace rmsc
