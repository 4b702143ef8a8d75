// Post pass and its display target.
#include "render/post_pass.hpp"

#include <stdexcept>

namespace rmsc {

DisplayTarget createDisplayTarget(int width, int height) {
    DisplayTarget target;
    target.width = width;
    target.height = height;
    target.color = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(target.color.id(), 1, GL_RGBA8, width, height);
    target.framebuffer = gl::createFramebuffer();
    glNamedFramebufferTexture(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, target.color.id(), 0);
    if (glCheckNamedFramebufferStatus(target.framebuffer.id(), GL_FRAMEBUFFER) !=
        GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the display framebuffer is incomplete");
    return target;
}

std::optional<PostPass> PostPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/fullscreen.vert", "passes/post.frag", ""}, error);
    if (!program) return std::nullopt;
    PostPass pass;
    pass.program_ = std::move(*program);
    pass.emptyVertexArray_ = gl::createVertexArray();
    return pass;
}

void PostPass::draw(const GBuffer& source, const DisplayTarget& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glBindTextureUnit(0, source.color.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTextureUnit(0, 0);
}

} // namespace rmsc
