// Shadow pass: depth only, with the raster pass's face culling seen from the light (a
// single-sided surface whose back faces the light casts no shadow, as the light does not see
// it), and a slope-scaled polygon offset as the depth bias (the shader adds a normal offset).
// MASK materials cast through their cut-outs; BLEND ones cast where their alpha is >= 0.5.
// Lines and points cast no shadow.
#include "render/shadow_pass.hpp"

#include "face_culling.hpp"

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
    pass.alphaTest_ = uniformLocation(pass.program_, "uAlphaTest");
    pass.uvTransform_ = uniformLocation(pass.program_, "uUvTransform");
    pass.jointBase_ = uniformLocation(pass.program_, "uJointBase");
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

void ShadowPass::bindAlphaTest(const GpuScene& scene, const GpuMeshInstance& instance,
                               const GpuMeshPrimitive& primitive) const {
    glm::vec3 test(-1.0f, 1.0f, -1.0f);
    glm::mat3 uvTransform(1.0f);
    GLuint texture = 0;
    if (instance.materialOverride < 0 && primitive.material >= 0) {
        const std::size_t index = std::size_t(primitive.material);
        const GpuMesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        const MeshMaterial& m = scene.meshMaterials[std::size_t(instance.mesh)][index];
        if (m.alphaMode != AlphaMode::Opaque) {
            test.x = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.5f;
            test.y = m.baseColorFactor.w;
            const int t =
                index < mesh.materialTextures.size() ? mesh.materialTextures[index].baseColor : -1;
            if (t >= 0) {
                test.z = float(m.baseColorTexture.texCoord);
                uvTransform = m.baseColorTexture.transform.matrix();
                texture = mesh.textures[std::size_t(t)].id();
            }
        }
    }
    glUniform3fv(alphaTest_, 1, glm::value_ptr(test));
    glUniformMatrix3fv(uvTransform_, 1, GL_FALSE, glm::value_ptr(uvTransform));
    glBindTextureUnit(0, texture);
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
            setFrontFace(instance);
            const GpuMesh& mesh = scene.meshes[std::size_t(instance.mesh)];
            bindJointMatrices(mesh);
            for (const GpuMeshPrimitive& primitive : mesh.primitives) {
                if (primitive.mode != GL_TRIANGLES) continue;
                glUniform1i(jointBase_, primitive.jointBase);
                setFaceCulling(drawsBothFaces(scene, instance, primitive));
                bindAlphaTest(scene, instance, primitive);
                glBindVertexArray(primitive.vertexArray.id());
                glDrawElements(GL_TRIANGLES, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
            }
        }
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        for (std::size_t i = 0; i < scene.shells.size() && i < shellPasses.size(); ++i)
            shellPasses[i]->drawDepth(scene.shells[i], scene.shadowViews[layer],
                                      scene.shadowSlopeBias);
    }
    glBindVertexArray(0);
    glBindTextureUnit(0, 0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

} // namespace rmsc
