// The render targets a geometry pass writes: HDR colour, world normal, linear view depth and
// object id (four colour attachments), plus a depth buffer.
#pragma once

#include "gl/handles.hpp"

namespace rmsc {

struct GBuffer {
    int width = 0;
    int height = 0;
    gl::Texture color;     // RGBA16F, linear HDR
    gl::Texture normal;    // RGBA16F, xyz = world normal (0 where nothing was hit)
    gl::Texture viewDepth; // R32F, distance along the view axis (kNoDepth where nothing was hit)
    gl::Texture objectId;  // R32UI, 0 = background
    gl::Texture depth;     // DEPTH_COMPONENT32F, window depth
    gl::Framebuffer framebuffer;

    // Clears every attachment: colour to `background`, depth to 1, view depth to kNoDepth.
    void clear(const float background[3]) const;
};

constexpr float kNoDepth = 1.0e30f;

GBuffer createGBuffer(int width, int height);

} // namespace rmsc
