// Uploading mesh assets: interleaved vertex buffers, 32-bit indices, sRGB textures.
#include "render/gpu_mesh.hpp"

#include <cmath>

namespace rmsc {

GpuMesh uploadMesh(const MeshAsset& asset) {
    GpuMesh mesh;
    for (const MeshPrimitive& source : asset.primitives) {
        GpuMeshPrimitive p;
        p.vertices = gl::createBufferWithData(
            GLsizeiptr(source.vertices.size() * sizeof(MeshVertex)), source.vertices.data());
        p.indices = gl::createBufferWithData(
            GLsizeiptr(source.indices.size() * sizeof(std::uint32_t)), source.indices.data());
        p.indexCount = GLsizei(source.indices.size());
        p.material = source.material;
        p.vertexArray = gl::createVertexArray();
        const GLuint vao = p.vertexArray.id();
        glVertexArrayVertexBuffer(vao, 0, p.vertices.id(), 0, sizeof(MeshVertex));
        glVertexArrayElementBuffer(vao, p.indices.id());
        const GLuint offsets[] = {offsetof(MeshVertex, position), offsetof(MeshVertex, normal),
                                  offsetof(MeshVertex, uv)};
        const GLint sizes[] = {3, 3, 2};
        for (GLuint a = 0; a < 3; ++a) {
            glEnableVertexArrayAttrib(vao, a);
            glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
            glVertexArrayAttribBinding(vao, a, 0);
        }
        mesh.primitives.push_back(std::move(p));
    }
    for (const Image& image : asset.images) {
        gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
        const int levels =
            1 + int(std::floor(std::log2(float(std::max(image.width, image.height)))));
        glTextureStorage2D(texture.id(), levels, GL_SRGB8_ALPHA8, image.width, image.height);
        glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA,
                            GL_UNSIGNED_BYTE, image.rgba.data());
        glGenerateTextureMipmap(texture.id());
        glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
        mesh.textures.push_back(std::move(texture));
    }
    return mesh;
}

} // namespace rmsc
