// The SDF layer's part of generated/constants.glsl: every opcode, modifier kind, profile type
// and operation appears once, with the number the C++ code uses, and the literals are GLSL.
#include "sdf/glsl_constants.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"
#include "sdf/program.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace rmsc;

namespace {

std::map<std::string, std::string> sdfConstants() {
    std::map<std::string, std::string> byName;
    for (const GlslConstant& constant : sdfGlslConstants())
        EXPECT_TRUE(byName.emplace(constant.name, constant.value).second) << constant.name;
    return byName;
}

} // namespace

TEST(GlslConstants, LiteralsAreGlsl) {
    EXPECT_EQ(glslUint(7), "7u");
    EXPECT_EQ(glslInt(-3), "-3");
    EXPECT_EQ(glslFloat(1e10f), "10000000000.0");
    EXPECT_EQ(glslFloat(0.25f), "0.25");
    EXPECT_EQ(glslName("rounded_rectangle"), "ROUNDED_RECTANGLE");
    const GlslConstant constants[] = {{"A", "1u"}, {"B", "2"}};
    EXPECT_EQ(glslDefines(constants), "#define A 1u\n#define B 2\n");
}

TEST(GlslConstants, SizesAndOpcodesAreTheCppValues) {
    const auto constants = sdfConstants();
    EXPECT_EQ(constants.at("SDF_MAX_STACK"), std::to_string(kSdfMaxStack));
    EXPECT_EQ(constants.at("SDF_MAX_POINT_STACK"), std::to_string(kSdfMaxPointStack));
    EXPECT_EQ(constants.at("SDF_UNIFORM_INSTRUCTIONS"), std::to_string(kSdfUniformInstructions));
    EXPECT_EQ(std::stof(constants.at("SDF_FAR")), kSdfFar);
    EXPECT_EQ(constants.at("SDF_OPCODE_SHAPE"), glslUint(std::uint32_t(SdfOpcode::Shape)));
    EXPECT_EQ(constants.at("SDF_OPCODE_POINT_MODIFIER"),
              glslUint(std::uint32_t(SdfOpcode::PointModifier)));
    EXPECT_EQ(constants.at("SDF_OPCODE_SEED_BEST"), glslUint(std::uint32_t(SdfOpcode::SeedBest)));
    // Every opcode from 0 to the last, each once.
    std::set<std::string> opcodes;
    for (const auto& [name, value] : constants)
        if (name.starts_with("SDF_OPCODE_")) {
            EXPECT_TRUE(opcodes.insert(value).second) << name;
        }
    EXPECT_EQ(opcodes.size(), std::size_t(SdfOpcode::SeedBest) + 1);
    for (std::uint32_t opcode = 0; opcode <= std::uint32_t(SdfOpcode::SeedBest); ++opcode)
        EXPECT_TRUE(opcodes.count(glslUint(opcode))) << opcode;
}

TEST(GlslConstants, EveryCatalogueRowHasItsKind) {
    const auto constants = sdfConstants();
    for (const ModifierSpec& spec : modifierCatalogue()) {
        const std::string prefix =
            spec.stage == ModifierStage::Point ? "SDF_POINT_" : "SDF_DISTANCE_";
        EXPECT_EQ(constants.at(prefix + glslName(spec.name)), glslUint(modifierKind(spec.type)));
    }
    for (const ProfileSpec& spec : profileCatalogue())
        EXPECT_EQ(constants.at("SDF_PROFILE_" + glslName(spec.name)),
                  glslUint(std::uint32_t(spec.type)));
    for (const OperationSpec& spec : operationCatalogue())
        EXPECT_EQ(constants.at("SDF_OP_" + glslName(spec.name)), glslUint(std::uint32_t(spec.op)));
    EXPECT_EQ(constants.at("SDF_POINT_TWIST"), "4u");
    EXPECT_EQ(constants.at("SDF_DISTANCE_DISPLACE"), "2u");
    EXPECT_EQ(constants.at("SDF_OP_ROUND_INTERSECTION"), "12u");
    EXPECT_EQ(constants.at("SDF_PROFILE_POLYGON"), "3u");
}
