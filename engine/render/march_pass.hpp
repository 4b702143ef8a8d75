// March pass: a fullscreen triangle that sphere-traces the SDF scene up to the raster depth and
// writes the combined G-buffer (SDF hits over the raster result).
#pragma once

#include "gl/program.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"

#include <optional>
#include <string>

namespace rmsc {

class MarchPass {
  public:
    static std::optional<MarchPass> create(const ShaderFiles& files, std::string& error);
    // Reads `raster`, writes every pixel of `target`. Expects the frame UBO and SSBOs bound.
    void draw(const GBuffer& raster, const GBuffer& target) const;

  private:
    gl::Program program_;
    gl::VertexArray emptyVertexArray_;
};

} // namespace rmsc
