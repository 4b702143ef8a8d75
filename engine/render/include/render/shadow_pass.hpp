// Shadow pass: renders the depth of every mesh instance and every shell into the layers of a
// shadow-map array, one layer per GpuScene::shadowViews entry. The fullscreen SDF objects are
// not drawn: they cast shadows by marching (shaders/common/shadows.glsl). MASK and BLEND
// materials are alpha-tested (passes/shadow.frag).
#pragma once

#include "gl/program.hpp"
#include "render/gpu_scene.hpp"
#include "render/shell_pass.hpp"

#include <optional>
#include <span>
#include <string>

namespace rmsc {

class ShadowPass {
  public:
    static std::optional<ShadowPass> create(const ShaderFiles& files, std::string& error);
    // Draws the scene's shadow views (the maps are reallocated when their size or count
    // changes); shellPasses[i] draws scene.shells[i]. Leaves the framebuffer binding and
    // viewport changed.
    void draw(const GpuScene& scene, std::span<const ShellPass* const> shellPasses);
    // The depth array (DEPTH_COMPONENT32F, compare mode on, linear filtering): always a
    // complete texture, 1x1x1 while no scene needs maps.
    const gl::Texture& maps() const { return maps_; }

  private:
    gl::Program program_;
    GLint model_ = -1, lightViewProjection_ = -1, alphaTest_ = -1, uvTransform_ = -1,
          jointBase_ = -1;
    gl::Texture maps_;
    gl::Framebuffer framebuffer_;
    int size_ = 0, layers_ = 0;

    void allocate(int size, int layers);
    // The alpha test of one primitive's material (MASK, BLEND) and its base colour texture.
    void bindAlphaTest(const GpuScene& scene, const GpuMeshInstance& instance,
                       const GpuMeshPrimitive& primitive) const;
};

} // namespace rmsc
