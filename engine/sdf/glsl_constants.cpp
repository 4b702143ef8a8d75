// The SDF layer's GLSL constants (sdf/glsl_constants.hpp).
#include "sdf/glsl_constants.hpp"

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"
#include "sdf/program.hpp"

#include <cctype>

namespace rmsc {
namespace {

// Every SdfOpcode with its GLSL name (SDF_OPCODE_ + name).
struct OpcodeName {
    SdfOpcode opcode;
    const char* name;
};
constexpr OpcodeName kOpcodes[] = {
    {SdfOpcode::Shape, "SHAPE"},           {SdfOpcode::Combine, "COMBINE"},
    {SdfOpcode::PushPoint, "PUSH_POINT"},  {SdfOpcode::PointModifier, "POINT_MODIFIER"},
    {SdfOpcode::PopPoint, "POP_POINT"},    {SdfOpcode::DistanceModifier, "DISTANCE_MODIFIER"},
    {SdfOpcode::Profile, "PROFILE"},       {SdfOpcode::BoundSkip, "BOUND_SKIP"},
    {SdfOpcode::Accumulate, "ACCUMULATE"}, {SdfOpcode::SeedBest, "SEED_BEST"},
};

} // namespace

std::string glslUint(std::uint32_t value) {
    return std::to_string(value) + "u";
}

std::string glslInt(int value) {
    return std::to_string(value);
}

std::string glslFloat(float value) {
    std::string text = shortestNumberText(value);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

std::string glslName(std::string_view name) {
    std::string out;
    for (char c : name)
        out += char(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::vector<GlslConstant> sdfGlslConstants() {
    std::vector<GlslConstant> out = {
        {"SDF_MAX_STACK", glslInt(kSdfMaxStack)},
        {"SDF_MAX_POINT_STACK", glslInt(kSdfMaxPointStack)},
        {"SDF_REGISTER_STACK", glslInt(kSdfRegisterStack)},
        {"SDF_REGISTER_POINT_STACK", glslInt(kSdfRegisterPointStack)},
        {"SDF_UNIFORM_INSTRUCTIONS", glslInt(kSdfUniformInstructions)},
        {"SDF_FAR", glslFloat(kSdfFar)},
        {"SDF_CELL_MAX_LEVELS", glslInt(limits::kSdfCellLevels)},
        {"SDF_CELL_AFFINE", glslUint(kSdfCellAffine)},
        {"SDF_CELL_PLANES", glslInt(kSdfCellPlanes)},
        {"SDF_ENTRY_INDEX_BITS", glslUint(kSdfEntryIndexBits)},
    };
    for (const OpcodeName& opcode : kOpcodes)
        out.push_back(
            {"SDF_OPCODE_" + std::string(opcode.name), glslUint(std::uint32_t(opcode.opcode))});
    for (const ModifierSpec& spec : modifierCatalogue()) {
        const char* prefix = spec.stage == ModifierStage::Point ? "SDF_POINT_" : "SDF_DISTANCE_";
        out.push_back({prefix + glslName(spec.name), glslUint(modifierKind(spec.type))});
    }
    for (const ProfileSpec& spec : profileCatalogue())
        out.push_back({"SDF_PROFILE_" + glslName(spec.name), glslUint(std::uint32_t(spec.type))});
    for (const OperationSpec& spec : operationCatalogue())
        out.push_back({"SDF_OP_" + glslName(spec.name), glslUint(std::uint32_t(spec.op))});
    return out;
}

std::string glslDefines(std::span<const GlslConstant> constants) {
    std::string out;
    for (const GlslConstant& constant : constants)
        out += "#define " + constant.name + " " + constant.value + "\n";
    return out;
}

} // namespace rmsc
