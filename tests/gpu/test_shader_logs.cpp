// Compiler and linker logs mapped back to the shader files (gl/shader_source.hpp): the
// locations of Mesa's compile logs and of NVIDIA's link logs, which report each stage's errors
// under a heading in that stage's numbering of files. No GL context needed.
#include "gl/shader_source.hpp"

#include <gtest/gtest.h>

using namespace rmsc;

namespace {

// A main file including "a.glsl", which includes "b.glsl": files 0, 1 and 2.
AssembledShader assembled(const char* main) {
    ShaderFiles files;
    files.files[main] = "#version 450 core\n#include \"a.glsl\"\nvoid main() {}\n";
    files.files["a.glsl"] = "#include \"b.glsl\"\nfloat a;\n";
    files.files["b.glsl"] = "float b;\n";
    std::string error;
    std::optional<AssembledShader> shader = assembleShader(files, main, "", error);
    EXPECT_TRUE(shader) << error;
    return shader ? *shader : AssembledShader{};
}

} // namespace

TEST(ShaderLogs, CompileLogsNameTheFileAndLine) {
    const AssembledShader shader = assembled("main.frag");
    ASSERT_EQ(shader.files.size(), 3u);
    EXPECT_EQ(mapShaderLog(shader, "2:1(7): error: syntax error"),
              "b.glsl:1:7: error: syntax error");
    EXPECT_EQ(mapShaderLog(shader, "1(2) : error C1068: array index out of bounds"),
              "a.glsl:2 : error C1068: array index out of bounds");
}

TEST(ShaderLogs, LinkLogsAreMappedPerStage) {
    const AssembledShader vertex = assembled("main.vert");
    const AssembledShader fragment = assembled("main.frag");
    const ShaderStageSource stages[] = {{"Vertex", &vertex}, {"Fragment", &fragment}};
    const std::string log = "Vertex info\n-----------\n0(3) : warning C7050: x\n"
                            "Fragment info\n-------------\n2(1) : error C1068: array index out "
                            "of bounds\n";
    EXPECT_EQ(mapLinkLog(stages, log),
              "Vertex info\n-----------\nmain.vert:3 : warning C7050: x\n"
              "Fragment info\n-------------\nb.glsl:1 : error C1068: array index out of bounds\n");
    // One stage: no heading needed.
    const ShaderStageSource compute[] = {{"Compute", &fragment}};
    EXPECT_EQ(mapLinkLog(compute, "1(2) : error C0000: x"), "a.glsl:2 : error C0000: x");
    // Before any heading of several stages, nothing is known to map with.
    EXPECT_EQ(mapLinkLog(stages, "0(3) : error"), "0(3) : error");
}
