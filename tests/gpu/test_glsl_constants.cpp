// generated/constants.glsl as the GLSL compiler reads it: a shader that includes it fails to
// compile unless each constant has the value of its C++ counterpart (a negative array size for
// any that differs), no shader file defines one of them again, and the shaders' buffers, blocks
// and samplers are bound where the C++ code binds them (read back by GL introspection).
#include "gpu_test_support.hpp"

#include "gl/program.hpp"
#include "render/cone_pass.hpp"
#include "render/gpu_layout.hpp"
#include "render/shader_library.hpp"
#include "scene/material_textures.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/program.hpp"

using namespace rmsc;
using namespace rmsc::test;

namespace {

struct Expected {
    std::string name;
    std::string value; // a GLSL literal of the C++ value
};

std::vector<Expected> expectedConstants() {
    std::vector<Expected> out = {
        {"SDF_MAX_STACK", std::to_string(kSdfMaxStack)},
        {"SDF_MAX_POINT_STACK", std::to_string(kSdfMaxPointStack)},
        {"SDF_UNIFORM_INSTRUCTIONS", std::to_string(kSdfUniformInstructions)},
        {"SDF_OPCODE_SHAPE", std::to_string(unsigned(SdfOpcode::Shape)) + "u"},
        {"SDF_OPCODE_COMBINE", std::to_string(unsigned(SdfOpcode::Combine)) + "u"},
        {"SDF_OPCODE_PUSH_POINT", std::to_string(unsigned(SdfOpcode::PushPoint)) + "u"},
        {"SDF_OPCODE_POINT_MODIFIER", std::to_string(unsigned(SdfOpcode::PointModifier)) + "u"},
        {"SDF_OPCODE_POP_POINT", std::to_string(unsigned(SdfOpcode::PopPoint)) + "u"},
        {"SDF_OPCODE_DISTANCE_MODIFIER",
         std::to_string(unsigned(SdfOpcode::DistanceModifier)) + "u"},
        {"SDF_OPCODE_PROFILE", std::to_string(unsigned(SdfOpcode::Profile)) + "u"},
        {"SDF_OPCODE_BOUND_SKIP", std::to_string(unsigned(SdfOpcode::BoundSkip)) + "u"},
        {"SDF_OPCODE_ACCUMULATE", std::to_string(unsigned(SdfOpcode::Accumulate)) + "u"},
        {"SDF_OPCODE_SEED_BEST", std::to_string(unsigned(SdfOpcode::SeedBest)) + "u"},
        {"SDF_PROFILE_CIRCLE", std::to_string(unsigned(SdfProfileType::Circle)) + "u"},
        {"SDF_PROFILE_POLYGON", std::to_string(unsigned(SdfProfileType::Polygon)) + "u"},
        {"SDF_OP_XOR", std::to_string(unsigned(SdfOp::Xor)) + "u"},
        {"SDF_OP_ROUND_UNION", std::to_string(unsigned(SdfOp::RoundUnion)) + "u"},
        {"SDF_PROGRAM_BINDING", std::to_string(kSdfProgramBinding)},
        {"MATERIAL_BINDING", std::to_string(kMaterialBinding)},
        {"LIGHT_BINDING", std::to_string(kLightBinding)},
        {"SHADOW_VIEW_BINDING", std::to_string(kShadowViewBinding)},
        {"SDF_DATA_BINDING", std::to_string(kSdfDataBinding)},
        {"MARCH_STATISTICS_BINDING", std::to_string(kMarchStatisticsBinding)},
        {"JOINT_MATRIX_BINDING", std::to_string(kJointMatrixBinding)},
        {"FRAME_BINDING", std::to_string(kFrameBinding)},
        {"SDF_PROGRAM_UNIFORM_BINDING", std::to_string(kSdfProgramUniformBinding)},
        {"SKY_IMAGE_UNIT", std::to_string(kSkyImageUnit)},
        {"SHADOW_MAP_UNIT", std::to_string(kShadowMapUnit)},
        {"SDF_PROGRAM_TEXEL_UNIT", std::to_string(kSdfProgramTexelUnit)},
        {"SDF_CELL_TEXEL_UNIT", std::to_string(kSdfCellTexelUnit)},
        {"SDF_TEXTURE_FIRST_UNIT", std::to_string(kSdfMaterialTextureFirstUnit)},
        {"SDF_TEXTURE_COUNT", std::to_string(kMaxSdfMaterialTextures)},
        {"CONE_START_UNIT", std::to_string(kConeStartUnit)},
        {"CONE_TILE_SIZE", std::to_string(kConeTileSize)},
        {"LIGHT_DIRECTIONAL", std::to_string(kGpuDirectional)},
        {"LIGHT_POINT", std::to_string(kGpuPoint)},
        {"LIGHT_SPOT", std::to_string(kGpuSpot)},
        {"SKY_NONE", std::to_string(int(SkyType::None))},
        {"SKY_IMAGE", std::to_string(int(SkyType::Image))},
    };
    for (const ModifierSpec& spec : modifierCatalogue())
        out.push_back(
            {std::string(spec.stage == ModifierStage::Point ? "SDF_POINT_" : "SDF_DISTANCE_") +
                 glslName(spec.name),
             std::to_string(modifierKind(spec.type)) + "u"});
    return out;
}

// A fragment shader that compiles only if every constant has its expected value.
std::string checkingShader(const std::vector<Expected>& expected) {
    std::string text = "#version 450 core\n#include \"generated/constants.glsl\"\n";
    for (const Expected& e : expected)
        text += "int check_" + e.name + "[(" + e.name + " == " + e.value + ") ? 1 : -1];\n";
    text += "out vec4 color;\nvoid main() { color = vec4(SDF_FAR); }\n";
    return text;
}

bool compiles(const std::string& fragment, std::string& error) {
    sharedRenderer(); // makes the context current
    ShaderFiles files = embeddedShaderFiles();
    files.files["test/constants.frag"] = fragment;
    return bool(buildProgram(files, {"passes/fullscreen.vert", "test/constants.frag", ""}, error));
}

GLint resource(const gl::Program& program, GLenum interface, const char* name, GLenum property) {
    const GLuint index = glGetProgramResourceIndex(program.id(), interface, name);
    EXPECT_NE(index, GL_INVALID_INDEX) << name;
    GLint value = -1;
    glGetProgramResourceiv(program.id(), interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

GLint samplerUnit(const gl::Program& program, const char* name) {
    const GLint location = glGetUniformLocation(program.id(), name);
    EXPECT_GE(location, 0) << name;
    GLint unit = -1;
    glGetUniformiv(program.id(), location, &unit);
    return unit;
}

} // namespace

TEST(GlslConstants, TheShaderCompilerSeesTheCppValues) {
    const std::vector<Expected> expected = expectedConstants();
    std::string error;
    EXPECT_TRUE(compiles(checkingShader(expected), error)) << error;
    // The check is real: one wrong value fails the compile.
    std::vector<Expected> wrong = expected;
    wrong[0].value = std::to_string(kSdfMaxStack + 1);
    EXPECT_FALSE(compiles(checkingShader(wrong), error));
    // That compile error is logged to the GL debug output too: taken here, where it is expected,
    // so a test after this one in the same process does not find it.
    takeGlDebugErrors();
}

TEST(GlslConstants, TheHeaderHoldsBothLayersConstantsOnce) {
    const std::string header = glslConstantsHeader();
    for (const Expected& e : expectedConstants()) {
        const std::string line = "#define " + e.name + " " + e.value + "\n";
        const std::size_t at = header.find(line);
        EXPECT_NE(at, std::string::npos) << line;
        EXPECT_EQ(header.find("#define " + e.name + " ", at + 1), std::string::npos) << e.name;
    }
}

TEST(GlslConstants, NoShaderFileDefinesAGeneratedConstantAgain) {
    std::vector<GlslConstant> constants = sdfGlslConstants();
    for (const GlslConstant& constant : renderGlslConstants())
        constants.push_back(constant);
    for (const auto& [path, text] : embeddedShaderFiles().files) {
        if (path.starts_with("generated/")) continue;
        for (const GlslConstant& constant : constants)
            EXPECT_EQ(text.find("#define " + constant.name + " "), std::string::npos)
                << path << " defines " << constant.name;
    }
}

TEST(GlslConstants, BuffersBlocksAndSamplersAreWhereTheRendererBindsThem) {
    sharedRenderer();
    ShaderFiles files = embeddedShaderFiles();
    files.files["test/bindings.frag"] = R"(#version 450 core
#include "common/lighting.glsl"
#include "common/sdf_scene.glsl"
#include "common/material_textures.glsl"
#include "common/march_statistics.glsl"
out vec4 color;
void main() {
    color = sdfUniformInstructions[0].params[0] + sdfInstructions[0].params[0] +
            sdfInstructionTexel(0u, 0) + sdfData[0] +
            materials[0].baseColorMetallic + lights[0].colorIntensity + shadowViews[0].params +
            frame.viewport + texture(uShadowMaps, vec4(0.5)) + texture(uSkyImage, vec2(0.5)) +
            vec4(float(marchStatistics[0]));
    for (int slot = 0; slot < SDF_TEXTURE_COUNT; ++slot) color += sampleSdfTexture(slot, vec2(0.5), 1.0);
})";
    std::string error;
    const std::optional<gl::Program> p =
        buildProgram(files, {"passes/fullscreen.vert", "test/bindings.frag", ""}, error);
    ASSERT_TRUE(p) << error;
    const auto storage = [&](const char* block) {
        return resource(*p, GL_SHADER_STORAGE_BLOCK, block, GL_BUFFER_BINDING);
    };
    EXPECT_EQ(storage("SdfProgramBuffer"), GLint(kSdfProgramBinding));
    EXPECT_EQ(storage("MaterialBuffer"), GLint(kMaterialBinding));
    EXPECT_EQ(storage("LightBuffer"), GLint(kLightBinding));
    EXPECT_EQ(storage("ShadowViewBuffer"), GLint(kShadowViewBinding));
    EXPECT_EQ(storage("SdfData"), GLint(kSdfDataBinding));
    EXPECT_EQ(storage("MarchStatisticsBuffer"), GLint(kMarchStatisticsBinding));
    EXPECT_EQ(resource(*p, GL_UNIFORM_BLOCK, "FrameBlock", GL_BUFFER_BINDING),
              GLint(kFrameBinding));
    EXPECT_EQ(resource(*p, GL_UNIFORM_BLOCK, "SdfProgramUniforms", GL_BUFFER_BINDING),
              GLint(kSdfProgramUniformBinding));
    EXPECT_EQ(samplerUnit(*p, "uShadowMaps"), GLint(kShadowMapUnit));
    EXPECT_EQ(samplerUnit(*p, "sdfProgramTexels"), GLint(kSdfProgramTexelUnit));
    EXPECT_EQ(samplerUnit(*p, "uSkyImage"), GLint(kSkyImageUnit));
    for (int slot = 0; slot < kMaxSdfMaterialTextures; ++slot) {
        const std::string name = "uSdfTexture" + std::to_string(slot);
        EXPECT_EQ(samplerUnit(*p, name.c_str()), GLint(kSdfMaterialTextureFirstUnit) + slot);
    }
    expectNoGlErrors();
}
