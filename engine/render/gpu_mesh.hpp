// A MeshAsset uploaded to GL: one vertex array per primitive and one texture per image.
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
    int material = -1; // index into MeshAsset::materials
};

struct GpuMesh {
    std::vector<GpuMeshPrimitive> primitives;
    std::vector<gl::Texture> textures; // per MeshAsset::images, SRGB8_ALPHA8 with mipmaps
};

GpuMesh uploadMesh(const MeshAsset& asset);

} // namespace rmsc
