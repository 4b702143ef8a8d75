// Grid pass: the viewer's ground grid. Lines every unit and every ten units on the plane y = 0,
// the x axis red and the z axis blue, blended into the HDR colour wherever the plane is nearer
// than what the frame already holds (depth-tested against the G-buffer's depth, never writing
// it), so meshes and SDF objects hide it. Only the colour changes: depth, normals and ids, and
// so every AOV and picking, stay as the scene alone makes them.
#pragma once

#include "gl/program.hpp"
#include "render/gbuffer.hpp"

#include <optional>
#include <string>

namespace rmsc {

class GridPass {
  public:
    static std::optional<GridPass> create(const ShaderFiles& files, std::string& error);
    // Blends the grid into `target`'s colour. Expects the frame UBO bound.
    void draw(const GBuffer& target) const;

  private:
    gl::Program program_;
    gl::VertexArray emptyVertexArray_;
};

} // namespace rmsc
