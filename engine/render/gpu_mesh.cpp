// Uploading mesh assets: interleaved vertex buffers, 32-bit indices, material textures, and
// the joints, weights and joint matrices of skinned primitives.
#include "render/gpu_mesh.hpp"

#include "render/gpu_layout.hpp"

#include "gpu_texture.hpp"

#include <map>
#include <tuple>

namespace rmsc {

namespace {

glm::vec3 boundsCentre(const MeshPrimitive& source) {
    if (source.vertices.empty()) return glm::vec3(0.0f);
    glm::vec3 lo = source.vertices[0].position, hi = lo;
    for (const MeshVertex& v : source.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    return 0.5f * (lo + hi);
}

} // namespace

void updateMeshVertices(const MeshAsset& asset, GpuMesh& mesh) {
    for (std::size_t i = 0; i < asset.primitives.size() && i < mesh.primitives.size(); ++i) {
        const MeshPrimitive& source = asset.primitives[i];
        GpuMeshPrimitive& target = mesh.primitives[i];
        target.centre = boundsCentre(source);
        const bool gpuSkinned = target.jointBase >= 0;
        if (gpuSkinned && !target.morphed) continue; // the joint matrices move it
        const std::vector<MeshVertex>& vertices =
            gpuSkinned ? source.bindVertices : source.vertices;
        if (vertices.empty()) continue;
        const std::size_t bytes = vertices.size() * sizeof(MeshVertex);
        glNamedBufferSubData(target.vertices.id(), 0, GLsizeiptr(bytes), vertices.data());
        mesh.vertexBytesUploaded += bytes;
    }
    if (mesh.jointMatrices.id() != 0 && !asset.jointMatrices.empty()) {
        const std::size_t bytes = asset.jointMatrices.size() * sizeof(glm::mat4);
        glNamedBufferSubData(mesh.jointMatrices.id(), 0, GLsizeiptr(bytes),
                             asset.jointMatrices.data());
        mesh.jointBytesUploaded += bytes;
    }
}

void bindJointMatrices(const GpuMesh& mesh) {
    if (mesh.jointMatrices.id() != 0)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kJointMatrixBinding, mesh.jointMatrices.id());
}

GpuMesh uploadMesh(const MeshAsset& asset) {
    GpuMesh mesh;
    for (const MeshPrimitive& source : asset.primitives) {
        GpuMeshPrimitive p;
        const bool skinned = source.jointBase >= 0 && !source.skin.empty() &&
                             source.bindVertices.size() == source.vertices.size() &&
                             source.skin.size() == source.vertices.size();
        const std::vector<MeshVertex>& vertices = skinned ? source.bindVertices : source.vertices;
        p.vertices = gl::createBufferWithData(GLsizeiptr(vertices.size() * sizeof(MeshVertex)),
                                              vertices.data());
        p.indices = gl::createBufferWithData(
            GLsizeiptr(source.indices.size() * sizeof(std::uint32_t)), source.indices.data());
        p.indexCount = GLsizei(source.indices.size());
        p.mode = source.mode == PrimitiveMode::Lines    ? GL_LINES
                 : source.mode == PrimitiveMode::Points ? GL_POINTS
                                                        : GL_TRIANGLES;
        p.material = source.material;
        p.centre = boundsCentre(source);
        p.vertexArray = gl::createVertexArray();
        const GLuint vao = p.vertexArray.id();
        glVertexArrayVertexBuffer(vao, 0, p.vertices.id(), 0, sizeof(MeshVertex));
        glVertexArrayElementBuffer(vao, p.indices.id());
        // Attribute locations as in shaders/passes/raster.vert.
        const GLuint offsets[] = {offsetof(MeshVertex, position), offsetof(MeshVertex, normal),
                                  offsetof(MeshVertex, uv),       offsetof(MeshVertex, uv1),
                                  offsetof(MeshVertex, tangent),  offsetof(MeshVertex, color)};
        const GLint sizes[] = {3, 3, 2, 2, 4, 4};
        for (GLuint a = 0; a < 6; ++a) {
            glEnableVertexArrayAttrib(vao, a);
            glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
            glVertexArrayAttribBinding(vao, a, 0);
        }
        if (skinned) {
            // Joints and weights as in shaders/common/skinning.glsl, from a second buffer.
            p.jointBase = source.jointBase;
            p.morphed = source.morphed;
            p.skin = gl::createBufferWithData(
                GLsizeiptr(source.skin.size() * sizeof(MeshSkinVertex)), source.skin.data());
            glVertexArrayVertexBuffer(vao, 1, p.skin.id(), 0, sizeof(MeshSkinVertex));
            const GLuint skinOffsets[] = {
                offsetof(MeshSkinVertex, joints0), offsetof(MeshSkinVertex, joints1),
                offsetof(MeshSkinVertex, weights0), offsetof(MeshSkinVertex, weights1)};
            for (GLuint a = 0; a < 4; ++a) {
                glEnableVertexArrayAttrib(vao, 6 + a);
                if (a < 2)
                    glVertexArrayAttribIFormat(vao, 6 + a, 4, GL_UNSIGNED_INT, skinOffsets[a]);
                else
                    glVertexArrayAttribFormat(vao, 6 + a, 4, GL_FLOAT, GL_FALSE, skinOffsets[a]);
                glVertexArrayAttribBinding(vao, 6 + a, 1);
            }
        }
        mesh.primitives.push_back(std::move(p));
    }
    if (!asset.jointMatrices.empty())
        mesh.jointMatrices = gl::createBufferWithData(
            GLsizeiptr(asset.jointMatrices.size() * sizeof(glm::mat4)), asset.jointMatrices.data());
    // Textures by (image, sRGB, sampler): a glTF image used with two samplers or in two
    // colour spaces becomes two GL textures.
    std::map<std::tuple<int, bool, int, int, int, int>, int> known;
    const auto textureFor = [&](const MeshTextureRef& ref, bool srgb) -> int {
        if (!ref.present() || std::size_t(ref.image) >= asset.images.size()) return -1;
        const auto key =
            std::make_tuple(ref.image, srgb, ref.sampler.magFilter, ref.sampler.minFilter,
                            ref.sampler.wrapS, ref.sampler.wrapT);
        if (const auto found = known.find(key); found != known.end()) return found->second;
        const int index = int(mesh.textures.size());
        mesh.textures.push_back(
            uploadTexture(asset.images[std::size_t(ref.image)], srgb, ref.sampler));
        known.emplace(key, index);
        return index;
    };
    for (const MeshMaterial& m : asset.materials) {
        GpuMeshMaterialTextures t;
        t.baseColor = textureFor(m.baseColorTexture, true);
        t.metallicRoughness = textureFor(m.metallicRoughnessTexture, false);
        t.normal = textureFor(m.normalTexture, false);
        t.emissive = textureFor(m.emissiveTexture, true);
        t.occlusion = textureFor(m.occlusionTexture, false);
        mesh.materialTextures.push_back(t);
    }
    return mesh;
}

} // namespace rmsc
