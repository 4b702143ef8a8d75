// Raster pass: draws every glTF mesh instance into a G-buffer with the shared PBR shading.
#pragma once

#include "gl/program.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"

#include <optional>
#include <string>

namespace rmsc {

class RasterPass {
  public:
    static std::optional<RasterPass> create(const ShaderFiles& files, std::string& error);
    // Clears `target` to the background, then draws. Expects the frame UBO and scene SSBOs bound.
    void draw(const GpuScene& scene, const glm::vec3& background, const GBuffer& target) const;

  private:
    gl::Program program_;
    GLint model_ = -1, normalMatrix_ = -1, baseColorFactor_ = -1, metallicRoughness_ = -1,
          emissive_ = -1, texCoord_ = -1, objectId_ = -1;
};

} // namespace rmsc
