// The two passes that put rmsc's SDF objects into a host program's frame: the first turns the
// host's depth texture into the raster G-buffer the march pass reads (so the march stops at the
// host's surfaces), the second writes the march's hits into the host's framebuffer, colour and
// depth, and leaves every other pixel as the host drew it.
#pragma once

#include "gl/program.hpp"
#include "render/gbuffer.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace rmsc {

// What the host hands over (render/host_camera.hpp has its camera).
struct HostTarget {
    GLuint depthTexture = 0; // GL_TEXTURE_2D of a depth format: read, never written here
    GLuint framebuffer = 0;  // the host's colour and that depth texture: written
    int x = 0;               // the viewport's lower-left corner in the host's framebuffer
    int y = 0;
    float farDepth = 1.0f;      // the window depth where the host drew nothing
    bool displayEncoded = true; // write exposure, tone curve and sRGB, or linear HDR colour
};

class HostPass {
  public:
    static std::optional<HostPass> create(const ShaderFiles& files, std::string& error);

    // Fills every pixel of `raster` from the host's depth at the viewport. Expects the frame
    // UBO bound.
    void importDepth(const HostTarget& host, const glm::mat4& inverseViewProjection,
                     const GBuffer& raster) const;
    // Writes the hits in `combined` into the host's framebuffer at the viewport (the size of
    // `combined`), colour and depth. Expects the frame UBO bound.
    void composite(const GBuffer& combined, const HostTarget& host) const;

  private:
    gl::Program depthProgram_;
    gl::Program compositeProgram_;
    GLint inverseViewProjection_ = -1, depthOffset_ = -1, farDepth_ = -1;
    GLint compositeOffset_ = -1, displayEncoded_ = -1;
    gl::VertexArray emptyVertexArray_;
    gl::Sampler depthSampler_; // nearest, no comparison: whatever the host set on its texture
};

} // namespace rmsc
