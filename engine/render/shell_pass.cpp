// Shell pass: back faces only, depth-tested, the depth written by the fragment shader.
#include "render/shell_pass.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace rmsc {

ShellPass::Locations ShellPass::locate(const gl::Program& program) {
    Locations at;
    at.objectToWorld = uniformLocation(program, "uObjectToWorld");
    at.worldToObject = uniformLocation(program, "uWorldToObject");
    at.distanceScale = uniformLocation(program, "uShellDistanceScale");
    at.clipMin = uniformLocation(program, "uShellClipMin");
    at.clipMax = uniformLocation(program, "uShellClipMax");
    at.clips = uniformLocation(program, "uShellClips");
    at.viewProjection = uniformLocation(program, "uViewProjection");
    return at;
}

std::optional<ShellPass> ShellPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> color =
        buildProgram(files, {"passes/shell.vert", "passes/shell.frag", ""}, error);
    if (!color) return std::nullopt;
    std::optional<gl::Program> depth =
        buildProgram(files, {"passes/shell.vert", "passes/shell_shadow.frag", ""}, error);
    if (!depth) return std::nullopt;
    ShellPass pass;
    pass.color_ = std::move(*color);
    pass.depth_ = std::move(*depth);
    pass.colorAt_ = locate(pass.color_);
    pass.depthAt_ = locate(pass.depth_);
    pass.inverseViewProjection_ = uniformLocation(pass.depth_, "uInverseViewProjection");
    pass.depthBias_ = uniformLocation(pass.depth_, "uDepthBias");
    pass.perspective_ = uniformLocation(pass.depth_, "uPerspective");
    return pass;
}

void ShellPass::setShell(const Locations& at, const GpuShell& shell) {
    glUniformMatrix4fv(at.objectToWorld, 1, GL_FALSE, glm::value_ptr(shell.objectToWorld));
    glUniformMatrix4fv(at.worldToObject, 1, GL_FALSE, glm::value_ptr(shell.worldToObject));
    glUniform1f(at.distanceScale, shell.distanceScale);
    glUniform3fv(at.clipMin, 1, glm::value_ptr(shell.clipMin));
    glUniform3fv(at.clipMax, 1, glm::value_ptr(shell.clipMax));
    glUniform1i(at.clips, shell.clipsContent ? 1 : 0);
}

// Back faces only: a proxy the camera is inside still covers the pixels it should, and each
// pixel marches once for a convex proxy.
static void drawProxy(const GpuShell& shell) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glBindVertexArray(shell.vertexArray.id());
    glDrawElements(GL_TRIANGLES, shell.indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
}

void ShellPass::draw(const GpuShell& shell, const glm::mat4& viewProjection,
                     const GBuffer& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glUseProgram(color_.id());
    setShell(colorAt_, shell);
    glUniformMatrix4fv(colorAt_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    drawProxy(shell);
}

void ShellPass::drawDepth(const GpuShell& shell, const GpuShadowView& view,
                          float depthBiasTexels) const {
    glUseProgram(depth_.id());
    setShell(depthAt_, shell);
    glUniformMatrix4fv(depthAt_.viewProjection, 1, GL_FALSE,
                       glm::value_ptr(view.lightViewProjection));
    const glm::mat4 inverse = glm::inverse(view.lightViewProjection);
    glUniformMatrix4fv(inverseViewProjection_, 1, GL_FALSE, glm::value_ptr(inverse));
    glUniform1f(depthBias_, view.params.x * depthBiasTexels);
    glUniform1f(perspective_, view.params.y);
    drawProxy(shell);
}

} // namespace rmsc
