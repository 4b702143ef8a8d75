// Saves the OpenGL state rmsc's passes and uploads change, sets it to what they expect, and
// restores it when destroyed: what a host program embedding rmsc finds again after a call.
// The list of what it covers is kSavedState in gl/state_guard.cpp (docs/embedding.md prints it).
#pragma once

#include "gl/gl.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace rmsc::gl {

class StateGuard {
  public:
    // Saves the state, then sets the defaults the passes assume: no scissor, stencil,
    // rasterizer discard, polygon offset or colour logic op, all colour channels and depth
    // writable, filled polygons, no pixel unpack buffer and tightly packed pixel transfers.
    StateGuard();
    ~StateGuard();
    StateGuard(const StateGuard&) = delete;
    StateGuard& operator=(const StateGuard&) = delete;

  private:
    struct Capability {
        GLenum name;
        GLboolean enabled;
    };
    struct Binding {
        GLenum target; // GL_TEXTURE_2D, ... (for textures); indexed buffer target otherwise
        GLuint unitOrIndex;
        GLint name;
        GLint64 offset = 0;
        GLint64 size = 0;
    };
    std::vector<Capability> capabilities_;
    std::vector<Binding> textures_;
    std::vector<GLint> samplers_;
    std::vector<Binding> buffers_;
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, program_ = 0, vertexArray_ = 0;
    GLint activeTexture_ = 0, arrayBuffer_ = 0, uniformBuffer_ = 0, storageBuffer_ = 0;
    GLint unpackBuffer_ = 0, packBuffer_ = 0;
    std::array<GLint, 4> viewport_{};
    std::array<GLint, 4> scissorBox_{};
    GLint depthFunc_ = 0, cullFaceMode_ = 0, frontFace_ = 0;
    GLint polygonMode_[2] = {}; // some drivers return front and back
    GLboolean depthMask_ = GL_TRUE;
    std::vector<GLboolean> blendEnabled_;              // per draw buffer
    std::vector<std::array<GLboolean, 4>> colorMasks_; // per draw buffer
    std::vector<std::array<GLint, 6>> blend_;          // per draw buffer: funcs, equations
    GLfloat polygonOffsetFactor_ = 0, polygonOffsetUnits_ = 0;
    GLfloat clearColor_[4] = {}, clearDepth_ = 1;
    std::array<GLint, 8> pixelStore_{};
};

} // namespace rmsc::gl
