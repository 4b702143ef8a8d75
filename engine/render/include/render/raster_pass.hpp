// Raster pass: draws every glTF mesh instance into a G-buffer with the shared PBR shading.
// OPAQUE and MASK primitives go into the raster G-buffer (MASK cut out at its alphaCutoff);
// BLEND primitives are drawn later, over the finished frame, sorted back to front. Lines are
// drawn one pixel wide and points kGltfPointSize pixels square, unlit (their base colour, as
// KHR_materials_unlit draws it), into the colour, depth and id targets alike.
#pragma once

#include "gl/program.hpp"
#include "render/frame.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"

#include <optional>
#include <string>

namespace rmsc {

// The size of a glTF point (mode POINTS) on screen, in pixels.
constexpr float kGltfPointSize = 3.0f;

class RasterPass {
  public:
    static std::optional<RasterPass> create(const ShaderFiles& files, std::string& error);
    // Clears `target` to the background, then draws the OPAQUE and MASK primitives (back faces
    // culled for single-sided materials). Expects the frame UBO and scene SSBOs bound.
    void draw(const GpuScene& scene, const glm::vec3& background, const GBuffer& target) const;
    // Blends the BLEND primitives over `target`'s colour (the frame after the march pass), far
    // to near by the distance of each primitive's centre from the camera, depth-tested against
    // `target`'s depth and writing none: the normal, depth and id attachments keep what is
    // behind them.
    void drawBlended(const GpuScene& scene, const FrameCamera& camera, const GBuffer& target) const;

  private:
    // Sets the material uniforms, textures and face culling of one primitive.
    void bindPrimitive(const GpuScene& scene, const GpuMeshInstance& instance,
                       const GpuMeshPrimitive& primitive) const;

    gl::Program program_;
    GLint model_ = -1, normalMatrix_ = -1, jointBase_ = -1, baseColorFactor_ = -1,
          metallicRoughness_ = -1, emissive_ = -1, texCoord_ = -1, uvTransform_ = -1, alpha_ = -1,
          objectId_ = -1;
};

} // namespace rmsc
