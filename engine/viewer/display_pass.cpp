// The viewer's display pass (see display_pass.hpp).
#include "display_pass.hpp"

#include <algorithm>

namespace rmsc::app {

std::optional<DisplayPass> DisplayPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program = buildProgram(
        files, {"passes/viewer_display.vert", "passes/viewer_display.frag", ""}, error);
    if (!program) return std::nullopt;
    DisplayPass pass;
    pass.program_ = std::move(*program);
    pass.emptyVertexArray_ = gl::createVertexArray();
    pass.mode_ = uniformLocation(pass.program_, "uMode");
    pass.selected_ = uniformLocation(pass.program_, "uSelected");
    pass.selectedCount_ = uniformLocation(pass.program_, "uSelectedCount");
    pass.depthRange_ = uniformLocation(pass.program_, "uDepthRange");
    pass.maxSteps_ = uniformLocation(pass.program_, "uMaxSteps");
    pass.viewportSize_ = uniformLocation(pass.program_, "uViewportSize");
    return pass;
}

void DisplayPass::draw(const DisplayInput& input) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
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
    glUseProgram(program_.id());
    glProgramUniform1i(program_.id(), mode_, int(input.mode));
    std::vector<GLuint> ranges;
    for (const auto& [first, last] : input.selected) {
        if (int(ranges.size()) == 2 * kOutlinedRanges) break;
        ranges.push_back(first);
        ranges.push_back(last);
    }
    if (!ranges.empty())
        glProgramUniform2uiv(program_.id(), selected_, GLsizei(ranges.size() / 2), ranges.data());
    glProgramUniform1i(program_.id(), selectedCount_, int(ranges.size() / 2));
    glProgramUniform2f(program_.id(), depthRange_, input.nearPlane, input.farPlane);
    glProgramUniform1f(program_.id(), maxSteps_, float(input.maxSteps));
    glProgramUniform2f(program_.id(), viewportSize_, float(input.width), float(input.height));
    glBindTextureUnit(0, input.frame->display.color.id());
    glBindTextureUnit(1, input.frame->combined.normal.id());
    glBindTextureUnit(2, input.frame->combined.viewDepth.id());
    glBindTextureUnit(3, input.frame->combined.objectId.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    for (GLuint unit = 0; unit < 4; ++unit)
        glBindTextureUnit(unit, 0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
}

} // namespace rmsc::app
