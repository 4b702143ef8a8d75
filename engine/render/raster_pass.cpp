// Raster pass: depth-tested, back faces kept (glTF double-sided or not, lit from both sides).
#include "render/raster_pass.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <array>

namespace rmsc {

std::optional<RasterPass> RasterPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/raster.vert", "passes/raster.frag", ""}, error);
    if (!program) return std::nullopt;
    RasterPass pass;
    pass.program_ = std::move(*program);
    pass.model_ = uniformLocation(pass.program_, "uModel");
    pass.normalMatrix_ = uniformLocation(pass.program_, "uNormalMatrix");
    pass.baseColorFactor_ = uniformLocation(pass.program_, "uBaseColorFactor");
    pass.metallicRoughness_ = uniformLocation(pass.program_, "uMetallicRoughness");
    pass.emissive_ = uniformLocation(pass.program_, "uEmissive");
    pass.texCoord_ = uniformLocation(pass.program_, "uTexCoord");
    pass.objectId_ = uniformLocation(pass.program_, "uObjectId");
    return pass;
}

void RasterPass::draw(const GpuScene& scene, const glm::vec3& background,
                      const GBuffer& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    const float clearColor[3] = {background.x, background.y, background.z};
    target.clear(clearColor);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());

    for (const GpuMeshInstance& instance : scene.instances) {
        if (instance.mesh < 0) continue;
        const GpuMesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        const std::vector<MeshMaterial>& meshMaterials =
            scene.meshMaterials[std::size_t(instance.mesh)];
        glUniformMatrix4fv(model_, 1, GL_FALSE, glm::value_ptr(instance.model));
        glUniformMatrix3fv(normalMatrix_, 1, GL_FALSE, glm::value_ptr(instance.normalMatrix));
        glUniform1ui(objectId_, instance.objectId);
        for (const GpuMeshPrimitive& primitive : mesh.primitives) {
            glm::vec4 baseColor(1.0f);
            // metallic, roughness, normal scale, occlusion strength
            glm::vec4 metallicRoughness(1.0f, 1.0f, 1.0f, 1.0f);
            glm::vec3 emissive(0.0f);
            // Per texture unit 0..4 (raster.frag): the texture and the TEXCOORD set it reads.
            std::array<int, 5> textures{-1, -1, -1, -1, -1};
            std::array<GLint, 5> texCoords{-1, -1, -1, -1, -1};
            if (instance.materialOverride >= 0) {
                const Material& m = scene.materials[std::size_t(instance.materialOverride)];
                baseColor = glm::vec4(m.baseColor, 1.0f);
                metallicRoughness = {m.metallic, m.roughness, 1.0f, 1.0f};
                emissive = m.emissive;
            } else if (primitive.material >= 0) {
                const std::size_t index = std::size_t(primitive.material);
                const MeshMaterial& m = meshMaterials[index];
                baseColor = m.baseColorFactor;
                metallicRoughness = {m.metallicFactor, m.roughnessFactor, m.normalScale,
                                     m.occlusionStrength};
                emissive = m.emissiveFactor * m.emissiveStrength;
                if (index < mesh.materialTextures.size()) {
                    const GpuMeshMaterialTextures& t = mesh.materialTextures[index];
                    textures = {t.baseColor, t.metallicRoughness, t.normal, t.emissive,
                                t.occlusion};
                    const MeshTextureRef* refs[] = {&m.baseColorTexture,
                                                    &m.metallicRoughnessTexture, &m.normalTexture,
                                                    &m.emissiveTexture, &m.occlusionTexture};
                    for (std::size_t u = 0; u < 5; ++u)
                        if (textures[u] >= 0) texCoords[u] = refs[u]->texCoord;
                }
            }
            glUniform4fv(baseColorFactor_, 1, glm::value_ptr(baseColor));
            glUniform4fv(metallicRoughness_, 1, glm::value_ptr(metallicRoughness));
            glUniform3fv(emissive_, 1, glm::value_ptr(emissive));
            glUniform1iv(texCoord_, 5, texCoords.data());
            for (std::size_t u = 0; u < 5; ++u)
                glBindTextureUnit(
                    GLuint(u), textures[u] >= 0 ? mesh.textures[std::size_t(textures[u])].id() : 0);
            glBindVertexArray(primitive.vertexArray.id());
            glDrawElements(GL_TRIANGLES, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    }
    glBindVertexArray(0);
    for (GLuint unit = 0; unit < 5; ++unit)
        glBindTextureUnit(unit, 0);
}

} // namespace rmsc
