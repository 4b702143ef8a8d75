// Grid pass (see grid_pass.hpp).
#include "render/grid_pass.hpp"

namespace rmsc {

std::optional<GridPass> GridPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/fullscreen.vert", "passes/grid.frag", ""}, error);
    if (!program) return std::nullopt;
    GridPass pass;
    pass.program_ = std::move(*program);
    pass.emptyVertexArray_ = gl::createVertexArray();
    return pass;
}

void GridPass::draw(const GBuffer& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    // Only the colour attachment: normal, view depth and id keep the scene's values.
    for (GLuint attachment = 1; attachment < 4; ++attachment)
        glColorMaski(attachment, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(program_.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    for (GLuint attachment = 1; attachment < 4; ++attachment)
        glColorMaski(attachment, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

} // namespace rmsc
