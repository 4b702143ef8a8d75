// Texture readback with a vertical flip (GL's first row is the bottom one).
#include "render/readback.hpp"

#include <algorithm>

namespace rmsc {
namespace {

template <class T>
Pixels<T> readTexture(const gl::Texture& texture, int width, int height, int channels,
                      GLenum format, GLenum type) {
    Pixels<T> pixels{width, height, channels, {}};
    pixels.data.resize(std::size_t(width) * height * channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0, format, type, GLsizei(pixels.data.size() * sizeof(T)),
                      pixels.data.data());
    const std::size_t row = std::size_t(width) * channels;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.data.begin() + std::ptrdiff_t(y * row),
                         pixels.data.begin() + std::ptrdiff_t((y + 1) * row),
                         pixels.data.begin() + std::ptrdiff_t((height - 1 - y) * row));
    return pixels;
}

} // namespace

Pixels<std::uint8_t> readDisplayColor(const FrameTargets& t) {
    return readTexture<std::uint8_t>(t.display.color, t.display.width, t.display.height, 4, GL_RGBA,
                                     GL_UNSIGNED_BYTE);
}

Pixels<float> readViewDepth(const FrameTargets& t) {
    return readTexture<float>(t.combined.viewDepth, t.combined.width, t.combined.height, 1, GL_RED,
                              GL_FLOAT);
}

Pixels<float> readNormals(const FrameTargets& t) {
    return readTexture<float>(t.combined.normal, t.combined.width, t.combined.height, 3, GL_RGB,
                              GL_FLOAT);
}

Pixels<float> readMarchSteps(const FrameTargets& t) {
    // The march pass keeps each pixel's step count in the normal target's w.
    const Pixels<float> rgba = readTexture<float>(t.combined.normal, t.combined.width,
                                                  t.combined.height, 4, GL_RGBA, GL_FLOAT);
    Pixels<float> steps{rgba.width, rgba.height, 1, {}};
    steps.data.resize(std::size_t(rgba.width) * rgba.height);
    for (std::size_t i = 0; i < steps.data.size(); ++i)
        steps.data[i] = rgba.data[i * 4 + 3];
    return steps;
}

Pixels<float> readConeTiles(const FrameTargets& t) {
    return readTexture<float>(t.cone.distance, t.cone.width, t.cone.height, 2, GL_RG, GL_FLOAT);
}

Pixels<std::uint32_t> readObjectIds(const FrameTargets& t) {
    return readTexture<std::uint32_t>(t.combined.objectId, t.combined.width, t.combined.height, 1,
                                      GL_RED_INTEGER, GL_UNSIGNED_INT);
}

Pixels<float> readHdrColor(const FrameTargets& t) {
    return readTexture<float>(t.combined.color, t.combined.width, t.combined.height, 3, GL_RGB,
                              GL_FLOAT);
}

} // namespace rmsc
