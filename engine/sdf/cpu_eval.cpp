// The CPU evaluator: the interpreter of shaders/common/sdf_scene.glsl written again with GLM,
// statement for statement (same stack, same formulas, same march rule), so CPU results predict
// what the shader computes.
#include "sdf/cpu_eval.hpp"

#include <algorithm>
#include <array>
#include <cassert>

namespace rmsc {
namespace {

// Distance reported by an empty program (SDF_FAR in the shader): nothing anywhere.
constexpr float kSdfFar = 1e10f;

// Distance of a shape instruction at world point p: the primitive at the local point, scaled
// back to world units (sdfShapeDistance in the shader).
float shapeDistance(const GpuSdfInstruction& instruction, glm::vec3 p) {
    const glm::vec4 p4(p, 1.0f);
    const glm::vec3 q(glm::dot(instruction.worldToLocal[0], p4),
                      glm::dot(instruction.worldToLocal[1], p4),
                      glm::dot(instruction.worldToLocal[2], p4));
    const PrimitiveParams params = {instruction.params[0].x, instruction.params[0].y,
                                    instruction.params[0].z, instruction.params[0].w,
                                    instruction.params[1].x, instruction.params[1].y,
                                    instruction.params[1].z, instruction.params[1].w,
                                    instruction.params[2].x, instruction.params[2].y,
                                    instruction.params[2].z, instruction.params[2].w};
    const PrimitiveSpec& spec = primitiveSpec(PrimitiveId(instruction.kind));
    return spec.distance(q, params.data()) * instruction.misc.x;
}

// sdfCombine in the shader: a (below) and b (top of the stack) combined with `op`, smoothness k.
// weightA is how much of a's material the result carries: 1 or 0 for the hard operations (the
// side that won; subtraction keeps a), the blend factor h for the smooth ones.
// Formulas: Inigo Quilez, "Smooth minimum" (polynomial quadratic),
// https://iquilezles.org/articles/smin/ and https://iquilezles.org/articles/distfunctions/.
float combine(SdfOp op, float a, float b, float k, float& weightA) {
    switch (op) {
    case SdfOp::Union:
        weightA = a <= b ? 1.0f : 0.0f;
        return std::min(a, b);
    case SdfOp::Subtraction:
        weightA = 1.0f;
        return std::max(a, -b);
    case SdfOp::Intersection:
        weightA = a >= b ? 1.0f : 0.0f;
        return std::max(a, b);
    case SdfOp::SmoothUnion: {
        const float h = std::clamp(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
        weightA = h;
        return glm::mix(b, a, h) - k * h * (1.0f - h);
    }
    case SdfOp::SmoothSubtraction: {
        const float h = std::clamp(0.5f - 0.5f * (b + a) / k, 0.0f, 1.0f);
        weightA = 1.0f;
        return glm::mix(a, -b, h) + k * h * (1.0f - h);
    }
    case SdfOp::SmoothIntersection:
        break;
    }
    const float h = std::clamp(0.5f - 0.5f * (b - a) / k, 0.0f, 1.0f);
    weightA = h;
    return glm::mix(b, a, h) + k * h * (1.0f - h);
}

SdfSurface shapeSurface(const GpuSdfInstruction& instruction, std::span<const Material> materials,
                        glm::vec3 p) {
    SdfSurface s; // defaults = Material's defaults, used for an index out of range
    s.distance = shapeDistance(instruction, p);
    s.objectId = instruction.objectId;
    if (instruction.material < materials.size()) {
        const Material& m = materials[instruction.material];
        s.baseColor = m.baseColor;
        s.metallic = m.metallic;
        s.emissive = m.emissive;
        s.roughness = m.roughness;
    }
    return s;
}

} // namespace

float sdfDistance(const SdfProgram& program, glm::vec3 p) {
    if (program.instructions.empty()) return kSdfFar;
    std::array<float, kSdfMaxStack> stack{};
    int top = 0; // number of entries on the stack
    for (const GpuSdfInstruction& instruction : program.instructions) {
        if (instruction.opcode == std::uint32_t(SdfOpcode::Shape)) {
            assert(top < kSdfMaxStack);
            stack[top] = shapeDistance(instruction, p);
            ++top;
        } else {
            assert(top >= 2);
            float weightA = 0.0f;
            const float b = stack[top - 1];
            const float a = stack[top - 2];
            stack[top - 2] =
                combine(SdfOp(instruction.kind), a, b, instruction.params[0].x, weightA);
            --top;
        }
    }
    return stack[0];
}

SdfSurface sdfSurface(const SdfProgram& program, std::span<const Material> materials, glm::vec3 p) {
    if (program.instructions.empty()) {
        SdfSurface none;
        none.distance = kSdfFar;
        return none;
    }
    std::array<SdfSurface, kSdfMaxStack> stack{};
    int top = 0;
    for (const GpuSdfInstruction& instruction : program.instructions) {
        if (instruction.opcode == std::uint32_t(SdfOpcode::Shape)) {
            assert(top < kSdfMaxStack);
            stack[top] = shapeSurface(instruction, materials, p);
            ++top;
        } else {
            assert(top >= 2);
            const SdfSurface b = stack[top - 1];
            const SdfSurface a = stack[top - 2];
            float w = 0.0f;
            const float d = combine(SdfOp(instruction.kind), a.distance, b.distance,
                                    instruction.params[0].x, w);
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
    return stack[0];
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

// Sphere tracing (Hart 1996, "Sphere tracing"), as sdfMarch in the shader.
std::optional<SdfHit> sdfCastRay(const SdfProgram& program, const RenderSettings& settings,
                                 glm::vec3 origin, glm::vec3 direction, float tMin, float tMax) {
    if (program.instructions.empty()) return std::nullopt;
    const float len = glm::length(direction);
    if (!(len > 0.0f)) return std::nullopt;
    const glm::vec3 rd = direction / len;
    float t = tMin;
    for (int i = 0; i < settings.maxSteps; ++i) {
        if (t > tMax) return std::nullopt;
        const glm::vec3 position = origin + rd * t;
        const float d = sdfDistance(program, position);
        if (d < settings.surfaceEpsilon * std::max(t, 1.0f)) return SdfHit{t, position, i + 1};
        t += d;
    }
    return std::nullopt;
}

} // namespace rmsc
