// March pass: a fullscreen triangle that sphere-traces the SDF scene up to the raster depth and
// writes the combined G-buffer (SDF hits over the raster result).
#pragma once

#include "gl/program.hpp"
#include "render/cone_pass.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"

#include <optional>
#include <string>

namespace rmsc {

class MarchPass {
  public:
    // `countEvaluations`: the instrumented variant, which adds the primitives each pixel
    // evaluated to the march statistics (Renderer::lastMarchStatistics).
    static std::optional<MarchPass> create(const ShaderFiles& files, std::string& error,
                                           bool countEvaluations = false);
    // Reads `raster` and where the cone pass let each tile start, writes every pixel of
    // `target`. Expects the frame UBO and SSBOs bound.
    void draw(const GBuffer& raster, const ConeTarget& cone, const GBuffer& target) const;

  private:
    gl::Program program_;
    gl::VertexArray emptyVertexArray_;
};

} // namespace rmsc
