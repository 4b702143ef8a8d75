// Cone pass and its target.
#include "render/cone_pass.hpp"

#include <stdexcept>

namespace rmsc {

ConeTarget createConeTarget(int width, int height) {
    ConeTarget target;
    target.width = (width + kConeTileSize - 1) / kConeTileSize;
    target.height = (height + kConeTileSize - 1) / kConeTileSize;
    target.distance = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(target.distance.id(), 1, GL_RG32F, target.width, target.height);
    glTextureParameteri(target.distance.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(target.distance.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    target.framebuffer = gl::createFramebuffer();
    glNamedFramebufferTexture(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, target.distance.id(),
                              0);
    if (glCheckNamedFramebufferStatus(target.framebuffer.id(), GL_FRAMEBUFFER) !=
        GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the cone pass's framebuffer is incomplete");
    target.clear();
    return target;
}

void ConeTarget::clear() const {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, zero);
}

std::optional<ConePass> ConePass::create(const ShaderFiles& files, std::string& error,
                                         bool countEvaluations) {
    std::optional<gl::Program> program =
        buildProgram(files,
                     {"passes/fullscreen.vert", "passes/cone.frag",
                      countEvaluations ? "#define SDF_COUNT_EVALUATIONS 1\n" : ""},
                     error);
    if (!program) return std::nullopt;
    ConePass pass;
    pass.program_ = std::move(*program);
    pass.emptyVertexArray_ = gl::createVertexArray();
    return pass;
}

void ConePass::draw(const ConeTarget& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

} // namespace rmsc
