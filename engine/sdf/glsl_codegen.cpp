// Generates the GLSL of the SDF map from the compiled postfix program (see glsl_codegen.hpp).
// The value stack becomes local variables s0..sN (depth known from the compiler), the point
// stack becomes one variable per point frame; each instruction becomes one statement.
#include "sdf/glsl_codegen.hpp"

#include "sdf/cell_pruning.hpp"
#include "sdf/cost_model.hpp"
#include "sdf/glsl_constants.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"
#include "sdf/sdf_tree.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <sstream>
#include <vector>

namespace rmsc {

std::string_view sdfStrategyName(SdfStrategy strategy) {
    switch (strategy) {
    case SdfStrategy::Interpreter:
        return "interpreter";
    case SdfStrategy::Buffer:
        return "buffer";
    case SdfStrategy::Baked:
        return "baked";
    case SdfStrategy::Cells:
        return "cells";
    }
    return "baked";
}

std::optional<SdfStrategy> parseSdfStrategy(std::string_view name) {
    for (SdfStrategy s :
         {SdfStrategy::Interpreter, SdfStrategy::Buffer, SdfStrategy::Baked, SdfStrategy::Cells})
        if (sdfStrategyName(s) == name) return s;
    return std::nullopt;
}

namespace {

// A GLSL float literal that reads back as exactly `value` (9 significant digits round-trip a
// float) and is never mistaken for an int.
std::string floatLiteral(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    std::string literal = text;
    if (literal.find_first_of(".en") == std::string::npos) literal += ".0";
    return literal;
}

std::string vec4Literal(const glm::vec4& v) {
    return "vec4(" + floatLiteral(v.x) + ", " + floatLiteral(v.y) + ", " + floatLiteral(v.z) +
           ", " + floatLiteral(v.w) + ")";
}

// Where the generated code takes instruction i's numbers from: literals or the buffer.
struct Operands {
    const SdfProgram& program;
    bool baked;        // the Baked strategy
    SdfLiveRange live; // under Baked, objects whose numbers still come from the buffer
    std::size_t base;  // where the program starts in the program buffer

    bool literal(std::size_t i) const {
        return baked && !live.contains(program.instructions[i].objectId);
    }
    // From the uniform window of the buffer where it reaches (kSdfUniformInstructions).
    std::string instruction(std::size_t i) const {
        const std::size_t index = base + i;
        return (index < std::size_t(kSdfUniformInstructions) ? "sdfUniformInstructions["
                                                             : "sdfInstructions[") +
               std::to_string(index) + "]";
    }
    std::string params(std::size_t i, int row) const {
        return literal(i) ? vec4Literal(program.instructions[i].params[row])
                          : instruction(i) + ".params[" + std::to_string(row) + "]";
    }
    std::string param(std::size_t i, int k) const {
        return literal(i) ? floatLiteral(program.instructions[i].params[k / 4][k % 4])
                          : instruction(i) + ".params[" + std::to_string(k / 4) + "][" +
                                std::to_string(k % 4) + "]";
    }
    std::string local(std::size_t i, const std::string& point) const {
        if (!literal(i))
            return "sdfAffine(" + instruction(i) + ".worldToLocal[0], " + instruction(i) +
                   ".worldToLocal[1], " + instruction(i) + ".worldToLocal[2], " + point + ")";
        const GpuSdfInstruction& in = program.instructions[i];
        return "sdfAffine(" + vec4Literal(in.worldToLocal[0]) + ", " +
               vec4Literal(in.worldToLocal[1]) + ", " + vec4Literal(in.worldToLocal[2]) + ", " +
               point + ")";
    }
    std::string scale(std::size_t i) const {
        return literal(i) ? floatLiteral(program.instructions[i].misc.x)
                          : instruction(i) + ".misc.x";
    }
    std::string material(std::size_t i) const {
        return literal(i) ? std::to_string(program.instructions[i].material) + "u"
                          : instruction(i) + ".material";
    }
    std::string objectId(std::size_t i) const {
        return literal(i) ? std::to_string(program.instructions[i].objectId) + "u"
                          : instruction(i) + ".objectId";
    }
};

// The body of sdfDistance (surface = false) or sdfSurface (surface = true).
void emitBody(std::ostream& out, const Operands& ops, bool surface) {
    const std::vector<GpuSdfInstruction>& code = ops.program.instructions;
    const char* slotType = surface ? "SdfSurface" : "float";
    const int depth = std::max(ops.program.stackDepth, 1);
    for (int slot = 0; slot < depth; ++slot)
        out << "    " << slotType << " s" << slot << ";\n";
    if (!surface) out << "    float w;\n";
    // Programs with bounds unite their parts into `best` (SdfOpcode::Accumulate). Generated code
    // evaluates every part and leaves the box tests and seeds to the interpreter: on llvmpipe a
    // box test's if block costs more than the parts it skips (the 100-shape grid baked: 28 ms
    // per frame with them, 17 ms without; a cold build, first frame included, 13 s and 4.4 s).
    bool accumulates = false;
    for (const GpuSdfInstruction& in : code)
        accumulates = accumulates || SdfOpcode(in.opcode) == SdfOpcode::Accumulate;
    if (accumulates)
        out << (surface ? "    SdfSurface best = sdfEmptySurface(p0);\n"
                        : "    float best = SDF_FAR;\n");
    int top = 0;
    int nextPoint = 1;           // p0 is the argument
    std::vector<int> pointStack; // saved point variables
    int point = 0;               // the current point variable
    auto slot = [](int index) { return "s" + std::to_string(index); };
    for (std::size_t i = 0; i < code.size(); ++i) {
        const GpuSdfInstruction& in = code[i];
        const std::string p = "p" + std::to_string(point);
        const std::string kind = std::to_string(in.kind) + "u";
        switch (SdfOpcode(in.opcode)) {
        case SdfOpcode::BoundSkip:
        case SdfOpcode::SeedBest:
            break;
        case SdfOpcode::Accumulate:
            if (surface) {
                out << "    if (" << slot(top - 1)
                    << ".distance < best.distance) best = " << slot(top - 1) << ";\n";
            } else {
                out << "    best = min(best, " << slot(top - 1) << ");\n";
            }
            --top;
            break;
        case SdfOpcode::Shape:
        case SdfOpcode::Profile: {
            out << "    SDF_COUNT_EVALUATION;\n";
            const std::string q = "q" + std::to_string(i);
            out << "    vec3 " << q << " = " << ops.local(i, p) << ";\n";
            std::string distance;
            if (SdfOpcode(in.opcode) == SdfOpcode::Shape) {
                const PrimitiveSpec& spec = primitiveSpec(PrimitiveId(in.kind));
                distance = primitiveGlslCall(spec, q, [&](int k) { return ops.param(i, k); });
            } else {
                distance = "sdfProfile(" + kind + ", " + q + ", " + ops.params(i, 0) + ", " +
                           ops.params(i, 1) + ", " + ops.params(i, 2) + ")";
            }
            distance += " * " + ops.scale(i);
            out << "    " << slot(top) << " = ";
            if (surface) {
                out << "sdfMaterialSurface(" << distance << ", " << ops.objectId(i) << ", "
                    << ops.material(i) << ", " << q << ");\n";
            } else {
                out << distance << ";\n";
            }
            ++top;
            break;
        }
        case SdfOpcode::PushPoint:
            pointStack.push_back(point);
            out << "    vec3 p" << nextPoint << " = " << ops.local(i, p) << ";\n";
            point = nextPoint++;
            break;
        case SdfOpcode::PointModifier:
            out << "    vec3 p" << nextPoint << " = sdfPointModifier(" << kind << ", " << p << ", "
                << ops.params(i, 0) << ", " << ops.params(i, 1) << ", " << ops.params(i, 2)
                << ");\n";
            point = nextPoint++;
            break;
        case SdfOpcode::PopPoint:
            point = pointStack.back();
            pointStack.pop_back();
            break;
        case SdfOpcode::DistanceModifier: {
            const std::string target = slot(top - 1) + (surface ? ".distance" : "");
            out << "    " << target << " = sdfDistanceModifier(" << kind << ", " << target << ", "
                << p << ", " << ops.params(i, 0) << ");\n";
            break;
        }
        case SdfOpcode::Combine:
            out << "    " << slot(top - 2) << " = ";
            if (surface) {
                out << "sdfCombineSurfaces(" << kind << ", " << slot(top - 2) << ", "
                    << slot(top - 1) << ", " << ops.params(i, 0) << ");\n";
            } else {
                out << "sdfCombine(" << kind << ", " << slot(top - 2) << ", " << slot(top - 1)
                    << ", " << ops.params(i, 0) << ", w);\n";
            }
            --top;
            break;
        }
    }
    out << (accumulates ? "    return best;\n" : "    return s0;\n");
}

// ---- What the interpreters run of the shared GLSL ----
//
// The interpreters read their instructions from the buffer, so each of their dispatches (the
// opcode, the primitive, the operation, the modifier, the profile) is a chain of branches. A GPU
// runs the branch a pixel takes; llvmpipe runs every branch of every `if`, masked, and the body
// of every loop at least once: an interpreted instruction costs there what every kind of
// instruction the shader holds costs. So the interpreters' text holds only the kinds the
// program uses: defines that leave out whole opcodes, and dispatches over the kinds used (each
// a call of the shared function with a constant kind, which the shader compiler folds to that
// kind's code). The text still does not depend on the number of instructions.

// A dispatch `signature` over the GLSL constant names `kinds` (at least one): each branch calls
// `call` with "KIND" replaced by the constant, the last one unconditionally.
std::string kindDispatch(const std::string& signature, const std::string& selector,
                         const std::vector<std::string>& kinds, const std::string& call) {
    const auto callFor = [&](const std::string& kind) {
        std::string text = call;
        for (std::size_t at; (at = text.find("KIND")) != std::string::npos;)
            text.replace(at, 4, kind);
        return text;
    };
    std::string out = signature + " {\n";
    for (std::size_t k = 0; k + 1 < kinds.size(); ++k)
        out += "    if (" + selector + " == " + kinds[k] + ") return " + callFor(kinds[k]) + ";\n";
    out += "    return " + callFor(kinds.back()) + ";\n}\n";
    return out;
}

// The defines and dispatches of the interpreters for the instructions `code` (the program's,
// and for the Cells strategy the union and the far cells' planes the pruning adds).
std::string interpreterFeatures(const std::vector<GpuSdfInstruction>& code, bool cells) {
    std::vector<bool> opcodes(16, false), ops(64, false), profiles(64, false);
    std::vector<bool> pointKinds(64, false), distanceKinds(64, false);
    std::vector<bool> blends(2, false); // SmoothBlend: the curves the smooth operations use
    for (const GpuSdfInstruction& in : code) {
        if (in.opcode >= opcodes.size()) continue;
        opcodes[in.opcode] = true;
        const auto mark = [&](std::vector<bool>& used) {
            if (in.kind < used.size()) used[in.kind] = true;
        };
        switch (SdfOpcode(in.opcode)) {
        case SdfOpcode::Combine:
            mark(ops);
            if (in.kind < operationCatalogue().size() &&
                operationSpec(SdfOp(in.kind)).seam == SdfOpSeam::Smooth)
                blends[in.params[0].y >= 0.5f] = true; // (as sdfSmoothMin reads it)
            break;
        case SdfOpcode::Profile:
            mark(profiles);
            break;
        case SdfOpcode::PointModifier:
            mark(pointKinds);
            break;
        case SdfOpcode::DistanceModifier:
            mark(distanceKinds);
            break;
        default:
            break;
        }
    }
    if (cells) { // the union the bounding hierarchy's parts are folded with
        opcodes[std::size_t(SdfOpcode::Combine)] = true;
        ops[std::size_t(SdfOp::Union)] = true;
    }
    const auto has = [&](SdfOpcode opcode) { return opcodes[std::size_t(opcode)]; };
    std::ostringstream out;
    const auto define = [&](const char* name, bool value) {
        out << "#define " << name << (value ? " 1\n" : " 0\n");
    };
    out << "#define SDF_FEATURES 1\n";
    define("SDF_HAS_PROFILES", has(SdfOpcode::Profile));
    define("SDF_HAS_COMBINE", has(SdfOpcode::Combine));
    define("SDF_HAS_POINT_FRAMES", has(SdfOpcode::PushPoint));
    define("SDF_HAS_POINT_MODIFIERS", has(SdfOpcode::PointModifier));
    define("SDF_HAS_DISTANCE_MODIFIERS", has(SdfOpcode::DistanceModifier));
    // The cells' lists hold no bounding hierarchy, but for a program whose tree cannot be read
    // (engine/sdf/cell_pruning.hpp).
    define("SDF_HAS_BOUNDS",
           (has(SdfOpcode::BoundSkip) || has(SdfOpcode::SeedBest) || has(SdfOpcode::Accumulate)) &&
               (!cells || sdfCellsNeedHierarchy(code)));
    std::vector<std::string> names;
    for (const ProfileSpec& spec : profileCatalogue())
        if (profiles[std::size_t(spec.type)]) names.push_back("SDF_PROFILE_" + glslName(spec.name));
    if (!names.empty())
        out << kindDispatch("float sdfProfileUsed(uint kind, vec3 q, vec4 a0, vec4 a1, vec4 a2)",
                            "kind", names, "sdfProfile(KIND, q, a0, a1, a2)");
    names.clear();
    for (const OperationSpec& spec : operationCatalogue())
        if (ops[std::size_t(spec.op)]) names.push_back("SDF_OP_" + glslName(spec.name));
    // Where the smooth operations all use one curve, the dispatch passes it as a constant and the
    // compiler drops the other: llvmpipe would run both at every combine (the 4,096-sphere tree
    // 39.7 -> 38.2 ms a frame). The text then changes when an edit brings in the other curve.
    const std::string params = blends[0] == blends[1] ? "opParams"
                               : blends[0]            ? "vec4(opParams.x, 0.0, opParams.zw)"
                                                      : "vec4(opParams.x, 1.0, opParams.zw)";
    if (!names.empty())
        out << kindDispatch(
            "float sdfCombineUsed(uint op, float a, float b, vec4 opParams, out float weightA)",
            "op", names, "sdfCombine(KIND, a, b, " + params + ", weightA)");
    std::vector<std::string> point, distance;
    for (const ModifierSpec& spec : modifierCatalogue()) {
        const std::uint32_t kind = modifierKind(spec.type);
        if (spec.stage == ModifierStage::Point && pointKinds[kind])
            point.push_back("SDF_POINT_" + glslName(spec.name));
        if (spec.stage == ModifierStage::Distance && distanceKinds[kind])
            distance.push_back("SDF_DISTANCE_" + glslName(spec.name));
    }
    if (!point.empty())
        out << kindDispatch(
            "vec3 sdfPointModifierUsed(uint kind, vec3 p, vec4 a0, vec4 a1, vec4 a2)", "kind",
            point, "sdfPointModifier(KIND, p, a0, a1, a2)");
    if (!distance.empty())
        out << kindDispatch("float sdfDistanceModifierUsed(uint kind, float d, vec3 p, vec4 a0)",
                            "kind", distance, "sdfDistanceModifier(KIND, d, p, a0)");
    return out.str();
}

} // namespace

// The lines of a Cells map that say what it assumes of its grid's lists (SdfCellFit).
constexpr std::string_view kShortListsDefine = "#define SDF_CELLS_SHORT_LISTS 1\n";
constexpr std::string_view kShallowStacksDefine = "#define SDF_CELLS_SHALLOW_STACKS 1\n";

SdfCellFit sdfMapCellFit(std::string_view map) {
    return {map.find(kShortListsDefine) != std::string_view::npos,
            map.find(kShallowStacksDefine) != std::string_view::npos};
}

SdfStrategy effectiveSdfStrategy(const SdfProgram& program, SdfStrategy requested) {
    if (requested == SdfStrategy::Interpreter || requested == SdfStrategy::Cells) return requested;
    int leaves = 0;
    for (const GpuSdfInstruction& in : program.instructions)
        leaves +=
            SdfOpcode(in.opcode) == SdfOpcode::Shape || SdfOpcode(in.opcode) == SdfOpcode::Profile;
    return leaves > kMaxGeneratedLeaves ||
                   sdfGeneratedStatements(program) > limits::kGeneratedCodeStatements
               ? SdfStrategy::Cells
               : requested;
}

std::string generateSdfMap(const SdfProgram& program, SdfStrategy requested,
                           const SdfMapNames& names, const SdfLiveRange& live, SdfCellFit cellFit) {
    const std::string& prefix = names.prefix;
    SdfStrategy strategy = effectiveSdfStrategy(program, requested);
    // The interpreter runs the scene's own map only (it reads the program from its start);
    // another map gets generated code reading the buffer.
    if ((strategy == SdfStrategy::Interpreter || strategy == SdfStrategy::Cells) &&
        (prefix != "sdf" || names.instructionBase != 0))
        strategy = SdfStrategy::Buffer;
    std::ostringstream out;
    out << "// Generated by engine/sdf/glsl_codegen.cpp, strategy " << sdfStrategyName(strategy);
    if (strategy == SdfStrategy::Interpreter || strategy == SdfStrategy::Cells) {
        // The same text for every program of these kinds.
        out << ".\n";
        std::vector<bool> used(std::size_t(PrimitiveId::Count), false);
        for (const GpuSdfInstruction& in : program.instructions)
            if (SdfOpcode(in.opcode) == SdfOpcode::Shape) used[in.kind] = true;
        // A scene with a plane (a floor) marches across the cells that hold only it in a step
        // (kSdfCellAffine); one without has no such cell the march would not leave anyway. The
        // grid's planes (SdfCellGrid::planes) are some of the program's plane instructions: the
        // shader reads as many header entries as there are such instructions, at most
        // kSdfCellPlanes (the text changes with their number up to that, not with the shapes').
        int planes = 0;
        for (const GpuSdfInstruction& in : program.instructions)
            planes += SdfOpcode(in.opcode) == SdfOpcode::Shape &&
                      in.kind == std::uint32_t(PrimitiveId::Plane);
        planes = std::min(planes, kSdfCellPlanes);
        if (strategy == SdfStrategy::Cells) used[std::size_t(PrimitiveId::Plane)] = true; // far
        out << generateGlslDispatch([&](PrimitiveId id) { return used[std::size_t(id)]; })
            << interpreterFeatures(program.instructions, strategy == SdfStrategy::Cells);
        if (strategy == SdfStrategy::Cells) {
            // (The lean loop reads one shape an iteration whatever the lists: one text.)
            const bool lean = sdfIsLeastOfShapes(program);
            out << (lean ? "#define SDF_CELLS_LEAN 1\n" : "")
                << (planes > 0 ? "#define SDF_CELLS_PLANES " + std::to_string(planes) + "\n"
                               : std::string())
                << (!lean && cellFit.shortLists ? kShortListsDefine : "")
                << (!lean && cellFit.shallowStacks ? kShallowStacksDefine : "")
                << "#include \"common/sdf_cells.glsl\"\n";
        } else
            out << (sdfIsPartsOnly(program) ? "#include \"common/sdf_parts_loop.glsl\"\n"
                                            : "#include \"common/sdf_interpreter.glsl\"\n");
        return out.str();
    }
    out << ", " << program.instructions.size() << " instructions.\n";
    if (program.instructions.empty()) {
        out << "bool " << prefix << "SceneEmpty() { return true; }\n"
            << "float " << prefix << "Distance(vec3 p0) { return SDF_FAR; }\n"
            << "SdfSurface " << prefix << "Surface(vec3 p0) { return sdfEmptySurface(p0); }\n";
        return out.str();
    }
    const bool baked = strategy == SdfStrategy::Baked;
    const Operands ops{program, baked, baked ? live : SdfLiveRange{}, names.instructionBase};
    if (baked && live.first <= live.last)
        out << "// Objects " << live.first << " to " << live.last << " read the buffer.\n";
    out << "bool " << prefix << "SceneEmpty() { return false; }\n\nfloat " << prefix
        << "Distance(vec3 p0) {\n";
    emitBody(out, ops, false);
    out << "}\n\nSdfSurface " << prefix << "Surface(vec3 p0) {\n";
    emitBody(out, ops, true);
    out << "}\n";
    return out.str();
}

} // namespace rmsc
