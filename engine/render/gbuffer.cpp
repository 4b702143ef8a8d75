// G-buffer creation and clearing.
#include "render/gbuffer.hpp"

#include <stdexcept>

namespace rmsc {
namespace {

gl::Texture createTarget(GLenum format, int width, int height) {
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, format, width, height);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

} // namespace

GBuffer createGBuffer(int width, int height) {
    GBuffer g;
    g.width = width;
    g.height = height;
    g.color = createTarget(GL_RGBA16F, width, height);
    g.normal = createTarget(GL_RGBA16F, width, height);
    g.viewDepth = createTarget(GL_R32F, width, height);
    g.objectId = createTarget(GL_R32UI, width, height);
    g.depth = createTarget(GL_DEPTH_COMPONENT32F, width, height);
    g.framebuffer = gl::createFramebuffer();
    const GLuint fb = g.framebuffer.id();
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, g.color.id(), 0);
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT1, g.normal.id(), 0);
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT2, g.viewDepth.id(), 0);
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT3, g.objectId.id(), 0);
    glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, g.depth.id(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                              GL_COLOR_ATTACHMENT3};
    glNamedFramebufferDrawBuffers(fb, 4, buffers);
    if (glCheckNamedFramebufferStatus(fb, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the G-buffer framebuffer is incomplete");
    return g;
}

void GBuffer::clear(const float background[3]) const {
    const GLuint fb = framebuffer.id();
    const float clearColor[4] = {background[0], background[1], background[2], 1.0f};
    const float zero[4] = {0, 0, 0, 0};
    const float noDepth[4] = {kNoDepth, 0, 0, 0};
    const GLuint noId[4] = {0, 0, 0, 0};
    const float one = 1.0f;
    glClearNamedFramebufferfv(fb, GL_COLOR, 0, clearColor);
    glClearNamedFramebufferfv(fb, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(fb, GL_COLOR, 2, noDepth);
    glClearNamedFramebufferuiv(fb, GL_COLOR, 3, noId);
    glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &one);
}

} // namespace rmsc
