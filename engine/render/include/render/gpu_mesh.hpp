// A MeshAsset uploaded to GL: one vertex array per primitive and the materials' textures.
#pragma once

#include "gl/handles.hpp"
#include "scene/mesh_asset.hpp"

#include <vector>

namespace rmsc {

struct GpuMeshPrimitive {
    gl::Buffer vertices;
    gl::Buffer indices;
    gl::VertexArray vertexArray;
    GLsizei indexCount = 0;
    GLenum mode = GL_TRIANGLES; // GL_TRIANGLES, GL_LINES or GL_POINTS (MeshPrimitive::mode)
    int material = -1;          // index into MeshAsset::materials
    glm::vec3 centre{0.0f};     // of the primitive's bounds, in the asset's space (blend order)
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
};

GpuMesh uploadMesh(const MeshAsset& asset);

// Writes the vertices of `asset` (posed again: the same primitives with the same vertex
// counts, scene/mesh_pose.hpp) over those `mesh` was uploaded with, and their centres.
void updateMeshVertices(const MeshAsset& asset, GpuMesh& mesh);

} // namespace rmsc
