// Post pass: exposure, ACES tone mapping and sRGB encoding into an 8-bit display target.
#pragma once

#include "gl/program.hpp"
#include "render/gbuffer.hpp"

#include <optional>
#include <string>

namespace rmsc {

// An RGBA8 colour target holding the final, display-ready image.
struct DisplayTarget {
    int width = 0;
    int height = 0;
    gl::Texture color;
    gl::Framebuffer framebuffer;
};

DisplayTarget createDisplayTarget(int width, int height);

class PostPass {
  public:
    static std::optional<PostPass> create(const ShaderFiles& files, std::string& error);
    void draw(const GBuffer& source, const DisplayTarget& target) const;

  private:
    gl::Program program_;
    gl::VertexArray emptyVertexArray_;
};

} // namespace rmsc
