// Host passes: both fullscreen triangles, depth test on with GL_ALWAYS so gl_FragDepth is
// written as computed.
#include "render/host_pass.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace rmsc {

std::optional<HostPass> HostPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> depth =
        buildProgram(files, {"passes/fullscreen.vert", "passes/host_depth.frag", ""}, error);
    if (!depth) return std::nullopt;
    std::optional<gl::Program> composite =
        buildProgram(files, {"passes/fullscreen.vert", "passes/host_composite.frag", ""}, error);
    if (!composite) return std::nullopt;
    HostPass pass;
    pass.depthProgram_ = std::move(*depth);
    pass.compositeProgram_ = std::move(*composite);
    pass.inverseViewProjection_ = uniformLocation(pass.depthProgram_, "uInverseViewProjection");
    pass.depthOffset_ = uniformLocation(pass.depthProgram_, "uOffset");
    pass.farDepth_ = uniformLocation(pass.depthProgram_, "uFarDepth");
    pass.compositeOffset_ = uniformLocation(pass.compositeProgram_, "uOffset");
    pass.displayEncoded_ = uniformLocation(pass.compositeProgram_, "uDisplayEncoded");
    pass.emptyVertexArray_ = gl::createVertexArray();
    pass.depthSampler_ = gl::createSampler();
    const GLuint sampler = pass.depthSampler_.id();
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return pass;
}

void HostPass::importDepth(const HostTarget& host, const glm::mat4& inverseViewProjection,
                           const GBuffer& raster) const {
    glBindFramebuffer(GL_FRAMEBUFFER, raster.framebuffer.id());
    glViewport(0, 0, raster.width, raster.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const GLuint program = depthProgram_.id();
    glUseProgram(program);
    glProgramUniformMatrix4fv(program, inverseViewProjection_, 1, GL_FALSE,
                              glm::value_ptr(inverseViewProjection));
    glProgramUniform2i(program, depthOffset_, host.x, host.y);
    glProgramUniform1f(program, farDepth_, host.farDepth);
    glBindTextureUnit(0, host.depthTexture);
    glBindSampler(0, depthSampler_.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    glBindTextureUnit(0, 0);
    glDepthFunc(GL_LESS);
}

void HostPass::composite(const GBuffer& combined, const HostTarget& host) const {
    glBindFramebuffer(GL_FRAMEBUFFER, host.framebuffer);
    glViewport(host.x, host.y, combined.width, combined.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS); // the march already stopped at the host's depth
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const GLuint program = compositeProgram_.id();
    glUseProgram(program);
    glProgramUniform2i(program, compositeOffset_, host.x, host.y);
    glProgramUniform1i(program, displayEncoded_, host.displayEncoded ? 1 : 0);
    glBindTextureUnit(0, combined.color.id());
    glBindTextureUnit(1, combined.objectId.id());
    glBindTextureUnit(2, combined.depth.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    for (GLuint unit = 0; unit < 3; ++unit)
        glBindTextureUnit(unit, 0);
    glDepthFunc(GL_LESS);
}

} // namespace rmsc
