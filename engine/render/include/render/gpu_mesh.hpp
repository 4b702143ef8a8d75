// A MeshAsset uploaded to GL: one vertex array per primitive, the materials' textures and the
// joint matrices skinned primitives are skinned with on the GPU.
#pragma once

#include "gl/handles.hpp"
#include "scene/mesh_asset.hpp"

#include <cstdint>
#include <vector>

namespace rmsc {

struct GpuMeshPrimitive {
    gl::Buffer vertices; // MeshVertex[]: MeshPrimitive::bindVertices when skinned, else vertices
    gl::Buffer skin;     // MeshSkinVertex[] of a skinned primitive (attributes 6 to 9), else none
    gl::Buffer indices;
    gl::VertexArray vertexArray;
    GLsizei indexCount = 0;
    GLenum mode = GL_TRIANGLES; // GL_TRIANGLES, GL_LINES or GL_POINTS (MeshPrimitive::mode)
    int material = -1;          // index into MeshAsset::materials
    glm::vec3 centre{0.0f};     // of the primitive's bounds, in the asset's space (blend order)
    int jointBase = -1;         // MeshPrimitive::jointBase: -1 when not skinned (uJointBase)
    bool morphed = false;       // MeshPrimitive::morphed: a new pose uploads its vertices again
};

// A material's textures as indices into GpuMesh::textures (-1 = none).
struct GpuMeshMaterialTextures {
    int baseColor = -1;
    int metallicRoughness = -1;
    int normal = -1;
    int emissive = -1;
    int occlusion = -1;
};

struct GpuMesh {
    std::vector<GpuMeshPrimitive> primitives;
    // One texture per distinct (image, colour space, sampler) the materials use, at the
    // image's own size with mipmaps: sRGB for base colour and emissive, linear otherwise.
    std::vector<gl::Texture> textures;
    std::vector<GpuMeshMaterialTextures> materialTextures; // per MeshAsset::materials
    // MeshAsset::jointMatrices (std430 mat4[]), bound at kJointMatrixBinding while the mesh is
    // drawn; none without skins. Its size is fixed at upload, as the skins are.
    gl::Buffer jointMatrices;
    // What updateMeshVertices wrote, in bytes: vertex buffers, and joint matrices.
    std::uint64_t vertexBytesUploaded = 0;
    std::uint64_t jointBytesUploaded = 0;
};

GpuMesh uploadMesh(const MeshAsset& asset);

// Writes the pose of `asset` (posed again: the same primitives with the same vertex counts,
// scene/mesh_pose.hpp) over the one `mesh` was uploaded with: the joint matrices, the vertices
// of primitives not skinned and of skinned ones with morph targets (their bind vertices), and
// the centres. A skinned primitive without morph targets uploads no vertices.
void updateMeshVertices(const MeshAsset& asset, GpuMesh& mesh);

// Binds the mesh's joint matrices at kJointMatrixBinding (nothing without skins).
void bindJointMatrices(const GpuMesh& mesh);

} // namespace rmsc
