// Shadow pass: depth only, both faces drawn (closed and open meshes alike), with a
// slope-scaled polygon offset as the depth bias (the shader adds a normal offset).
#include "render/shadow_pass.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>

namespace rmsc {

std::optional<ShadowPass> ShadowPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/shadow.vert", "passes/shadow.frag", ""}, error);
    if (!program) return std::nullopt;
    ShadowPass pass;
    pass.program_ = std::move(*program);
    pass.model_ = uniformLocation(pass.program_, "uModel");
    pass.lightViewProjection_ = uniformLocation(pass.program_, "uLightViewProjection");
    pass.framebuffer_ = gl::createFramebuffer();
    glNamedFramebufferDrawBuffer(pass.framebuffer_.id(), GL_NONE);
    glNamedFramebufferReadBuffer(pass.framebuffer_.id(), GL_NONE);
    pass.allocate(1, 1);
    return pass;
}

void ShadowPass::allocate(int size, int layers) {
    if (size == size_ && layers == layers_) return;
    maps_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(maps_.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
    glTextureParameteri(maps_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(maps_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(maps_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(maps_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(maps_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(maps_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    size_ = size;
    layers_ = layers;
    // Until drawn, every texel is at the far plane (lit).
    glNamedFramebufferTextureLayer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, maps_.id(), 0, 0);
    for (int layer = 0; layer < layers; ++layer) {
        glNamedFramebufferTextureLayer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, maps_.id(), 0,
                                       layer);
        const float one = 1.0f;
        glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &one);
    }
}

void ShadowPass::draw(const GpuScene& scene, std::span<const ShellPass* const> shellPasses) {
    if (scene.shadowViews.empty() || scene.shadowMapSize <= 0) return;
    allocate(scene.shadowMapSize, int(scene.shadowViews.size()));
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, size_, size_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(scene.shadowSlopeBias, 2.0f * scene.shadowSlopeBias);
    for (std::size_t layer = 0; layer < scene.shadowViews.size(); ++layer) {
        glUseProgram(program_.id());
        glNamedFramebufferTextureLayer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, maps_.id(), 0,
                                       GLint(layer));
        if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) !=
            GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("the shadow map framebuffer is incomplete");
        const float one = 1.0f;
        glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &one);
        glUniformMatrix4fv(lightViewProjection_, 1, GL_FALSE,
                           glm::value_ptr(scene.shadowViews[layer].lightViewProjection));
        for (const GpuMeshInstance& instance : scene.instances) {
            if (instance.mesh < 0) continue;
            glUniformMatrix4fv(model_, 1, GL_FALSE, glm::value_ptr(instance.model));
            for (const GpuMeshPrimitive& primitive :
                 scene.meshes[std::size_t(instance.mesh)].primitives) {
                glBindVertexArray(primitive.vertexArray.id());
                glDrawElements(GL_TRIANGLES, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
            }
        }
        for (std::size_t i = 0; i < scene.shells.size() && i < shellPasses.size(); ++i)
            shellPasses[i]->drawDepth(scene.shells[i], scene.shadowViews[layer],
                                      scene.shadowSlopeBias);
    }
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

} // namespace rmsc
