// March pass: no depth test (every pixel is written, hits with their own gl_FragDepth).
#include "render/march_pass.hpp"

namespace rmsc {

std::optional<MarchPass> MarchPass::create(const ShaderFiles& files, std::string& error,
                                           bool countEvaluations) {
    std::optional<gl::Program> program =
        buildProgram(files,
                     {"passes/fullscreen.vert", "passes/march.frag",
                      countEvaluations ? "#define SDF_COUNT_EVALUATIONS 1\n" : ""},
                     error);
    if (!program) return std::nullopt;
    MarchPass pass;
    pass.program_ = std::move(*program);
    pass.emptyVertexArray_ = gl::createVertexArray();
    return pass;
}

void MarchPass::draw(const GBuffer& raster, const ConeTarget& cone, const GBuffer& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glBindTextureUnit(0, raster.color.id());
    glBindTextureUnit(1, raster.normal.id());
    glBindTextureUnit(2, raster.viewDepth.id());
    glBindTextureUnit(3, raster.objectId.id());
    glBindTextureUnit(4, raster.depth.id());
    glBindTextureUnit(kConeStartUnit, cone.distance.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    for (GLuint unit = 0; unit < 5; ++unit)
        glBindTextureUnit(unit, 0);
    glBindTextureUnit(kConeStartUnit, 0);
    glDepthFunc(GL_LESS);
}

} // namespace rmsc
