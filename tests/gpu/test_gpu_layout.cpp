// The C++ mirrors of the shader's buffers have the layout the GLSL compiler gives them: offsets
// and strides are read back from the linked program by GL introspection.
#include "gpu_test_support.hpp"

#include "gl/program.hpp"
#include "render/frame.hpp"
#include "render/gpu_layout.hpp"
#include "render/shader_library.hpp"
#include "sdf/program.hpp"

using namespace rmsc;
using namespace rmsc::test;

namespace {

// A program that uses every scene buffer and the frame block, so none is optimized away.
gl::Program buildLayoutProbe() {
    sharedRenderer(); // makes the context current
    ShaderFiles files = embeddedShaderFiles();
    files.files["test/probe.frag"] = R"(#version 450 core
#include "common/lighting.glsl"
#include "common/sdf_scene.glsl"
out vec4 color;
void main() {
    SdfInstruction i = sdfInstructions[int(gl_FragCoord.x)];
    SdfInstruction u = sdfUniformInstructions[int(gl_FragCoord.y)];
    color = u.params[0] + u.params[2] + u.worldToLocal[2] + u.misc +
            vec4(u.opcode + u.kind + u.material + u.objectId + sdfUniformHeader.x) + i.params[0] + i.params[1] + i.worldToLocal[2] + i.misc + vec4(i.opcode + i.kind +
            i.material + i.objectId + sdfHeader.x) + materials[1].emissiveRoughness +
            vec4(float(materials[1].baseColorTexture.slot) + materials[1].baseColorTexture.scale +
                 materials[1].normalTexture.strength + materials[1].roughnessTexture.sharpness) +
            lights[1].colorIntensity + lights[1].positionRange + lights[1].spotShadow +
            shadowViews[1].lightViewProjection[2] + shadowViews[1].params + frame.viewport +
            frame.march + frame.sky + frame.fog + frame.ao + frame.shadowMap;
})";
    std::string error;
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/fullscreen.vert", "test/probe.frag", ""}, error);
    EXPECT_TRUE(program) << error;
    return program ? std::move(*program) : gl::Program();
}

GLint resourceProperty(const gl::Program& program, GLenum interface, const char* name,
                       GLenum property) {
    const GLuint index = glGetProgramResourceIndex(program.id(), interface, name);
    EXPECT_NE(index, GL_INVALID_INDEX) << name;
    GLint value = -1;
    glGetProgramResourceiv(program.id(), interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

GLint offsetOf(const gl::Program& p, const char* name) {
    return resourceProperty(p, GL_BUFFER_VARIABLE, name, GL_OFFSET);
}

} // namespace

TEST(GpuLayout, SdfInstructionMatchesTheShader) {
    const gl::Program p = buildLayoutProbe();
    EXPECT_EQ(offsetOf(p, "sdfInstructions[0].opcode"), GLint(sizeof(GpuSdfHeader)));
    EXPECT_EQ(resourceProperty(p, GL_BUFFER_VARIABLE, "sdfInstructions[0].opcode",
                               GL_TOP_LEVEL_ARRAY_STRIDE),
              GLint(sizeof(GpuSdfInstruction)));
    const GLint base = GLint(sizeof(GpuSdfHeader));
    EXPECT_EQ(offsetOf(p, "sdfInstructions[0].kind"),
              base + GLint(offsetof(GpuSdfInstruction, kind)));
    EXPECT_EQ(offsetOf(p, "sdfInstructions[0].objectId"),
              base + GLint(offsetof(GpuSdfInstruction, objectId)));
    EXPECT_EQ(offsetOf(p, "sdfInstructions[0].params[0]"),
              base + GLint(offsetof(GpuSdfInstruction, params)));
    EXPECT_EQ(offsetOf(p, "sdfInstructions[0].worldToLocal[0]"),
              base + GLint(offsetof(GpuSdfInstruction, worldToLocal)));
    EXPECT_EQ(offsetOf(p, "sdfInstructions[0].misc"),
              base + GLint(offsetof(GpuSdfInstruction, misc)));
    expectNoGlErrors();
}

// The uniform window of the program buffer (std140) reads the same bytes as the storage view
// (std430), and fits the size the C++ side binds.
TEST(GpuLayout, SdfUniformInstructionsMatchTheStorageLayout) {
    const gl::Program p = buildLayoutProbe();
    auto uniformOffset = [&](const char* name) {
        return resourceProperty(p, GL_UNIFORM, name, GL_OFFSET);
    };
    const GLint base = GLint(sizeof(GpuSdfHeader));
    EXPECT_EQ(uniformOffset("sdfUniformHeader"), 0);
    EXPECT_EQ(uniformOffset("sdfUniformInstructions[0].opcode"), base);
    EXPECT_EQ(uniformOffset("sdfUniformInstructions[0].objectId"),
              base + GLint(offsetof(GpuSdfInstruction, objectId)));
    EXPECT_EQ(uniformOffset("sdfUniformInstructions[0].params[0]"),
              base + GLint(offsetof(GpuSdfInstruction, params)));
    EXPECT_EQ(
        resourceProperty(p, GL_UNIFORM, "sdfUniformInstructions[0].params[0]", GL_ARRAY_STRIDE),
        16);
    EXPECT_EQ(uniformOffset("sdfUniformInstructions[0].worldToLocal[0]"),
              base + GLint(offsetof(GpuSdfInstruction, worldToLocal)));
    EXPECT_EQ(uniformOffset("sdfUniformInstructions[0].misc"),
              base + GLint(offsetof(GpuSdfInstruction, misc)));
    EXPECT_EQ(uniformOffset("sdfUniformInstructions[1].opcode"),
              base + GLint(sizeof(GpuSdfInstruction)));
    const GLuint block = glGetProgramResourceIndex(p.id(), GL_UNIFORM_BLOCK, "SdfProgramUniforms");
    ASSERT_NE(block, GL_INVALID_INDEX);
    const GLenum properties[] = {GL_BUFFER_DATA_SIZE, GL_BUFFER_BINDING};
    GLint values[2] = {-1, -1};
    glGetProgramResourceiv(p.id(), GL_UNIFORM_BLOCK, block, 2, properties, 2, nullptr, values);
    EXPECT_EQ(values[0], kSdfUniformBlockBytes);
    EXPECT_EQ(values[1], GLint(kSdfProgramUniformBinding));
    expectNoGlErrors();
}

TEST(GpuLayout, MaterialsAndLightsMatchTheShader) {
    const gl::Program p = buildLayoutProbe();
    EXPECT_EQ(resourceProperty(p, GL_BUFFER_VARIABLE, "materials[0].baseColorMetallic",
                               GL_TOP_LEVEL_ARRAY_STRIDE),
              GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(offsetOf(p, "materials[0].emissiveRoughness"),
              GLint(offsetof(GpuMaterial, emissiveRoughness)));
    EXPECT_EQ(offsetOf(p, "materials[0].baseColorTexture.slot"),
              GLint(offsetof(GpuMaterial, baseColorTexture) + offsetof(GpuMaterialTexture, slot)));
    EXPECT_EQ(offsetOf(p, "materials[0].baseColorTexture.scale"),
              GLint(offsetof(GpuMaterial, baseColorTexture) + offsetof(GpuMaterialTexture, scale)));
    EXPECT_EQ(offsetOf(p, "materials[0].normalTexture.strength"),
              GLint(offsetof(GpuMaterial, normalTexture) + offsetof(GpuMaterialTexture, strength)));
    EXPECT_EQ(
        offsetOf(p, "materials[0].roughnessTexture.sharpness"),
        GLint(offsetof(GpuMaterial, roughnessTexture) + offsetof(GpuMaterialTexture, sharpness)));
    EXPECT_EQ(offsetOf(p, "lights[0].directionType"), GLint(sizeof(GpuLightHeader)));
    EXPECT_EQ(resourceProperty(p, GL_BUFFER_VARIABLE, "lights[0].directionType",
                               GL_TOP_LEVEL_ARRAY_STRIDE),
              GLint(sizeof(GpuLight)));
    EXPECT_EQ(offsetOf(p, "lights[0].colorIntensity"),
              GLint(sizeof(GpuLightHeader) + offsetof(GpuLight, colorIntensity)));
    EXPECT_EQ(offsetOf(p, "lights[0].positionRange"),
              GLint(sizeof(GpuLightHeader) + offsetof(GpuLight, positionRange)));
    EXPECT_EQ(offsetOf(p, "lights[0].spotShadow"),
              GLint(sizeof(GpuLightHeader) + offsetof(GpuLight, spotShadow)));
}

TEST(GpuLayout, ShadowViewsMatchTheShader) {
    const gl::Program p = buildLayoutProbe();
    EXPECT_EQ(resourceProperty(p, GL_BUFFER_VARIABLE, "shadowViews[0].lightViewProjection",
                               GL_TOP_LEVEL_ARRAY_STRIDE),
              GLint(sizeof(GpuShadowView)));
    EXPECT_EQ(offsetOf(p, "shadowViews[0].lightViewProjection"),
              GLint(offsetof(GpuShadowView, lightViewProjection)));
    EXPECT_EQ(offsetOf(p, "shadowViews[0].params"), GLint(offsetof(GpuShadowView, params)));
}

TEST(GpuLayout, FrameBlockMatchesTheShader) {
    const gl::Program p = buildLayoutProbe();
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.viewport", GL_OFFSET),
              GLint(offsetof(GpuFrame, viewport)));
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.march", GL_OFFSET),
              GLint(offsetof(GpuFrame, march)));
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.frustumCorners", GL_OFFSET),
              GLint(offsetof(GpuFrame, frustumCorners)));
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.sky", GL_OFFSET),
              GLint(offsetof(GpuFrame, sky)));
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.fog", GL_OFFSET),
              GLint(offsetof(GpuFrame, fog)));
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.shadowMap", GL_OFFSET),
              GLint(offsetof(GpuFrame, shadowMap)));
    EXPECT_EQ(resourceProperty(p, GL_UNIFORM, "FrameBlock.ao", GL_OFFSET),
              GLint(offsetof(GpuFrame, ao)));
    const GLuint block = glGetProgramResourceIndex(p.id(), GL_UNIFORM_BLOCK, "FrameBlock");
    const GLenum property = GL_BUFFER_DATA_SIZE;
    GLint size = 0;
    glGetProgramResourceiv(p.id(), GL_UNIFORM_BLOCK, block, 1, &property, 1, nullptr, &size);
    EXPECT_EQ(size, GLint(sizeof(GpuFrame)));
}

// A compile error inside an included file is reported with that file's name and line.
TEST(ShaderErrors, CompileErrorNamesTheIncludedFileAndLine) {
    sharedRenderer();
    ShaderFiles files = embeddedShaderFiles();
    files.files["test/broken.glsl"] = "// line 1\nfloat ok() { return 1.0; }\nfloat broken() { "
                                      "return undefinedName; }\n";
    files.files["test/main.frag"] = "#version 450 core\n#include \"test/broken.glsl\"\nout vec4 "
                                    "c;\nvoid main() { c = vec4(broken()); }\n";
    std::string error;
    EXPECT_FALSE(buildProgram(files, {"passes/fullscreen.vert", "test/main.frag", ""}, error));
    EXPECT_NE(error.find("test/broken.glsl:3"), std::string::npos) << error;
    EXPECT_NE(error.find("undefinedName"), std::string::npos) << error;
    takeGlDebugErrors(); // the compile error is also a debug message: not the next test's
}
