// Texture upload (see gpu_texture.hpp).
#include "gpu_texture.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {

gl::Texture uploadTexture(const Image& image, bool srgb, const MeshSampler& sampler) {
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
    const int width = std::max(image.width, 1), height = std::max(image.height, 1);
    const int levels = 1 + int(std::floor(std::log2(float(std::max(width, height)))));
    glTextureStorage2D(texture.id(), levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, width, height);
    if (image.rgba.size() == std::size_t(width) * std::size_t(height) * 4) {
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE,
                            image.rgba.data());
    }
    glGenerateTextureMipmap(texture.id());
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, sampler.minFilter);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, sampler.magFilter);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, sampler.wrapS);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, sampler.wrapT);
    return texture;
}

} // namespace rmsc
