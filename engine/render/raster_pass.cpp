// Raster pass: depth-tested; back faces culled for single-sided glTF materials and lit with
// flipped normals for double-sided ones; MASK cut out in the shader; BLEND drawn last, sorted;
// lines and points drawn unlit.
#include "render/raster_pass.hpp"

#include "face_culling.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>

namespace rmsc {

namespace {

// The material of a primitive as drawn: the glTF material, or nullptr for a scene material
// override or the glTF default material (opaque, single-sided).
const MeshMaterial* materialOf(const GpuScene& scene, const GpuMeshInstance& instance,
                               const GpuMeshPrimitive& primitive) {
    if (instance.materialOverride >= 0 || primitive.material < 0) return nullptr;
    return &scene.meshMaterials[std::size_t(instance.mesh)][std::size_t(primitive.material)];
}

bool isBlended(const MeshMaterial* m) {
    return m && m->alphaMode == AlphaMode::Blend;
}

} // namespace

std::optional<RasterPass> RasterPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/raster.vert", "passes/raster.frag", ""}, error);
    if (!program) return std::nullopt;
    RasterPass pass;
    pass.program_ = std::move(*program);
    pass.model_ = uniformLocation(pass.program_, "uModel");
    pass.normalMatrix_ = uniformLocation(pass.program_, "uNormalMatrix");
    pass.jointBase_ = uniformLocation(pass.program_, "uJointBase");
    pass.baseColorFactor_ = uniformLocation(pass.program_, "uBaseColorFactor");
    pass.metallicRoughness_ = uniformLocation(pass.program_, "uMetallicRoughness");
    pass.emissive_ = uniformLocation(pass.program_, "uEmissive");
    pass.texCoord_ = uniformLocation(pass.program_, "uTexCoord");
    pass.uvTransform_ = uniformLocation(pass.program_, "uUvTransform");
    pass.alpha_ = uniformLocation(pass.program_, "uAlpha");
    pass.objectId_ = uniformLocation(pass.program_, "uObjectId");
    return pass;
}

void RasterPass::bindPrimitive(const GpuScene& scene, const GpuMeshInstance& instance,
                               const GpuMeshPrimitive& primitive) const {
    const GpuMesh& mesh = scene.meshes[std::size_t(instance.mesh)];
    // Skinned on the GPU (shaders/common/skinning.glsl): the mesh's joint matrices.
    glUniform1i(jointBase_, primitive.jointBase);
    if (primitive.jointBase >= 0) bindJointMatrices(mesh);
    glm::vec4 baseColor(1.0f);
    // metallic, roughness, normal scale, occlusion strength
    glm::vec4 metallicRoughness(1.0f, 1.0f, 1.0f, 1.0f);
    glm::vec3 emissive(0.0f);
    // alpha mode (0 opaque, 1 mask, 2 blend), alpha cutoff, unlit (0 or 1)
    glm::vec4 alpha(0.0f, 0.5f, 0.0f, 0.0f);
    // Per texture unit 0..4 (raster.frag): the texture and the TEXCOORD set it reads.
    std::array<int, 5> textures{-1, -1, -1, -1, -1};
    std::array<GLint, 5> texCoords{-1, -1, -1, -1, -1};
    std::array<glm::mat3, 5> uvTransforms{};
    uvTransforms.fill(glm::mat3(1.0f));
    if (instance.materialOverride >= 0) {
        const Material& m = scene.materials[std::size_t(instance.materialOverride)];
        baseColor = glm::vec4(m.baseColor, 1.0f);
        metallicRoughness = {m.metallic, m.roughness, 1.0f, 1.0f};
        emissive = m.emissive;
    } else if (const MeshMaterial* m = materialOf(scene, instance, primitive)) {
        const std::size_t index = std::size_t(primitive.material);
        baseColor = m->baseColorFactor;
        metallicRoughness = {m->metallicFactor, m->roughnessFactor, m->normalScale,
                             m->occlusionStrength};
        emissive = m->emissiveFactor * m->emissiveStrength;
        alpha.x = float(int(m->alphaMode));
        alpha.y = m->alphaCutoff;
        alpha.z = m->unlit ? 1.0f : 0.0f;
        if (index < mesh.materialTextures.size()) {
            const GpuMeshMaterialTextures& t = mesh.materialTextures[index];
            textures = {t.baseColor, t.metallicRoughness, t.normal, t.emissive, t.occlusion};
            const MeshTextureRef* refs[] = {&m->baseColorTexture, &m->metallicRoughnessTexture,
                                            &m->normalTexture, &m->emissiveTexture,
                                            &m->occlusionTexture};
            for (std::size_t u = 0; u < 5; ++u)
                if (textures[u] >= 0) {
                    texCoords[u] = refs[u]->texCoord;
                    uvTransforms[u] = refs[u]->transform.matrix();
                }
        }
    }
    // Lines and points have no surface to light: their base colour, as KHR_materials_unlit.
    if (primitive.mode != GL_TRIANGLES) alpha.z = 1.0f;
    setFaceCulling(drawsBothFaces(scene, instance, primitive));
    glUniform4fv(baseColorFactor_, 1, glm::value_ptr(baseColor));
    glUniform4fv(metallicRoughness_, 1, glm::value_ptr(metallicRoughness));
    glUniform3fv(emissive_, 1, glm::value_ptr(emissive));
    glUniform4fv(alpha_, 1, glm::value_ptr(alpha));
    glUniform1iv(texCoord_, 5, texCoords.data());
    glUniformMatrix3fv(uvTransform_, 5, GL_FALSE, glm::value_ptr(uvTransforms[0]));
    for (std::size_t u = 0; u < 5; ++u)
        glBindTextureUnit(GLuint(u),
                          textures[u] >= 0 ? mesh.textures[std::size_t(textures[u])].id() : 0);
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
    glDisable(GL_BLEND);
    glPointSize(kGltfPointSize);
    glUseProgram(program_.id());

    for (const GpuMeshInstance& instance : scene.instances) {
        if (instance.mesh < 0) continue;
        const GpuMesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        glUniformMatrix4fv(model_, 1, GL_FALSE, glm::value_ptr(instance.model));
        glUniformMatrix3fv(normalMatrix_, 1, GL_FALSE, glm::value_ptr(instance.normalMatrix));
        glUniform1ui(objectId_, instance.objectId);
        setFrontFace(instance);
        for (const GpuMeshPrimitive& primitive : mesh.primitives) {
            if (isBlended(materialOf(scene, instance, primitive))) continue;
            bindPrimitive(scene, instance, primitive);
            glBindVertexArray(primitive.vertexArray.id());
            glDrawElements(primitive.mode, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    }
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glPointSize(1.0f);
    for (GLuint unit = 0; unit < 5; ++unit)
        glBindTextureUnit(unit, 0);
}

void RasterPass::drawBlended(const GpuScene& scene, const FrameCamera& camera,
                             const GBuffer& target) const {
    struct Item {
        const GpuMeshInstance* instance;
        const GpuMeshPrimitive* primitive;
        float distance; // of the primitive's centre from the camera
    };
    std::vector<Item> items;
    for (const GpuMeshInstance& instance : scene.instances) {
        if (instance.mesh < 0) continue;
        for (const GpuMeshPrimitive& primitive :
             scene.meshes[std::size_t(instance.mesh)].primitives)
            if (isBlended(materialOf(scene, instance, primitive))) {
                const glm::vec3 centre = glm::vec3(instance.model * glm::vec4(primitive.centre, 1));
                items.push_back({&instance, &primitive, glm::length(centre - camera.position)});
            }
    }
    if (items.empty()) return;
    // Far to near; equal distances keep the file's order.
    std::stable_sort(items.begin(), items.end(),
                     [](const Item& a, const Item& b) { return a.distance > b.distance; });

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    // Colour only, "over" compositing of straight alpha; the other attachments are kept.
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glColorMaski(2, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glColorMaski(3, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glPointSize(kGltfPointSize);
    glUseProgram(program_.id());
    for (const Item& item : items) {
        const GpuMeshInstance& instance = *item.instance;
        glUniformMatrix4fv(model_, 1, GL_FALSE, glm::value_ptr(instance.model));
        glUniformMatrix3fv(normalMatrix_, 1, GL_FALSE, glm::value_ptr(instance.normalMatrix));
        glUniform1ui(objectId_, instance.objectId);
        setFrontFace(instance);
        bindPrimitive(scene, instance, *item.primitive);
        glBindVertexArray(item.primitive->vertexArray.id());
        glDrawElements(item.primitive->mode, item.primitive->indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glPointSize(1.0f);
    glDisablei(GL_BLEND, 0);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glDepthMask(GL_TRUE);
    for (GLuint a = 1; a < 4; ++a)
        glColorMaski(a, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (GLuint unit = 0; unit < 5; ++unit)
        glBindTextureUnit(unit, 0);
}

} // namespace rmsc
