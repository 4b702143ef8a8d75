// Cone pass: the march pass's low-resolution pre-pass. One fragment per tile of
// kConeTileSize x kConeTileSize pixels marches a cone around the tile's rays and writes how far
// all of them may skip; the march pass starts each pixel's march there (shaders/passes/cone.frag
// derives the bound).
#pragma once

#include "gl/program.hpp"

#include <optional>
#include <string>

namespace rmsc {

// Pixels per tile side (CONE_TILE_SIZE in the shaders, generated/constants.glsl).
constexpr int kConeTileSize = 8;

// Texture unit of the cone target in the march pass (uConeStart in shaders/passes/march.frag,
// CONE_START_UNIT).
constexpr unsigned kConeStartUnit = 13;

// One texel per tile: x = the distance every ray of the tile may skip, y = the cone's steps.
struct ConeTarget {
    int width = 0; // tiles
    int height = 0;
    gl::Texture distance; // RG32F
    gl::Framebuffer framebuffer;

    // Every tile skips nothing: the march pass then marches from the near plane.
    void clear() const;
};

// The tiles covering a width x height frame.
ConeTarget createConeTarget(int width, int height);

class ConePass {
  public:
    // `countEvaluations`: the instrumented variant (MarchPass::create).
    static std::optional<ConePass> create(const ShaderFiles& files, std::string& error,
                                          bool countEvaluations = false);
    // Writes every tile of `target`. Expects the frame UBO and the SDF buffers bound.
    void draw(const ConeTarget& target) const;

  private:
    gl::Program program_;
    gl::VertexArray emptyVertexArray_;
};

} // namespace rmsc
