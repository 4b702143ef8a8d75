// The viewer's display pass (see display_pass.hpp).
#include "display_pass.hpp"

#include <algorithm>
#include <string>

namespace rmsc::app {

std::optional<DisplayPass> DisplayPass::create(const ShaderFiles& files, std::string& error) {
    DisplayPass pass;
    for (int mode = 0; mode < kModes; ++mode) {
        for (int outlined = 0; outlined < 2; ++outlined) {
            const std::string defines = "#define DISPLAY_MODE " + std::to_string(mode) +
                                        "\n#define DISPLAY_OUTLINE " + std::to_string(outlined) +
                                        "\n";
            std::optional<gl::Program> program = buildProgram(
                files, {"passes/viewer_display.vert", "passes/viewer_display.frag", defines},
                error);
            if (!program) return std::nullopt;
            Variant v;
            v.program = std::move(*program);
            v.selected = uniformLocation(v.program, "uSelected");
            v.selectedCount = uniformLocation(v.program, "uSelectedCount");
            v.depthRange = uniformLocation(v.program, "uDepthRange");
            v.maxSteps = uniformLocation(v.program, "uMaxSteps");
            v.viewportSize = uniformLocation(v.program, "uViewportSize");
            pass.variants_.push_back(std::move(v));
        }
    }
    pass.emptyVertexArray_ = gl::createVertexArray();
    pass.linear_ = gl::createSampler();
    glSamplerParameteri(pass.linear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(pass.linear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(pass.linear_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(pass.linear_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return pass;
}

void DisplayPass::draw(const DisplayInput& input) const {
    glBindFramebuffer(GL_FRAMEBUFFER, input.framebuffer);
    glViewport(input.x, input.y, input.width, input.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (input.rows >= 0) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(input.x, input.y, input.width, std::min(input.rows, input.height));
    } else {
        glDisable(GL_SCISSOR_TEST);
    }
    glDisable(GL_CULL_FACE);
    std::vector<GLuint> ranges;
    for (const auto& [first, last] : input.selected) {
        if (int(ranges.size()) == 2 * kOutlinedRanges) break;
        ranges.push_back(first);
        ranges.push_back(last);
    }
    const int mode = std::clamp(int(input.mode), 0, kModes - 1);
    const Variant& v = variants_[std::size_t(2 * mode + (ranges.empty() ? 0 : 1))];
    const GLuint program = v.program.id();
    glUseProgram(program);
    if (!ranges.empty())
        glProgramUniform2uiv(program, v.selected, GLsizei(ranges.size() / 2), ranges.data());
    glProgramUniform1i(program, v.selectedCount, int(ranges.size() / 2));
    glProgramUniform2f(program, v.depthRange, input.nearPlane, input.farPlane);
    glProgramUniform1f(program, v.maxSteps, float(input.maxSteps));
    glProgramUniform2f(program, v.viewportSize, float(input.width), float(input.height));
    glBindTextureUnit(0, input.frame->display.color.id());
    glBindSampler(0, linear_.id());
    glBindTextureUnit(1, input.frame->combined.normal.id());
    glBindTextureUnit(2, input.frame->combined.viewDepth.id());
    glBindTextureUnit(3, input.frame->combined.objectId.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    for (GLuint unit = 0; unit < 4; ++unit)
        glBindTextureUnit(unit, 0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
}

} // namespace rmsc::app
