// Shell pass (mesh-shell mode): draws one shell's proxy mesh and marches the shell's SDF in its
// fragments, into the raster G-buffer after the meshes (so the march pass stops at shells as it
// does at meshes), and into the shadow maps through a depth-only variant. One ShellPass per
// shell map: its programs include the scene's map (for shadows and ambient occlusion) and the
// shell's.
#pragma once

#include "gl/program.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"

#include <optional>
#include <string>

namespace rmsc {

class ShellPass {
  public:
    // `files` holds "generated/sdf_map.glsl" and "generated/shell_map.glsl".
    static std::optional<ShellPass> create(const ShaderFiles& files, std::string& error);
    // Draws `shell` into `target` (depth-tested against what is there). Expects the frame UBO,
    // the scene's SSBOs, the shadow maps and the sky bound.
    void draw(const GpuShell& shell, const glm::mat4& viewProjection, const GBuffer& target) const;
    // Draws `shell` into the bound shadow-map layer of `view`; depthBiasTexels pushes its depth
    // away from the light.
    void drawDepth(const GpuShell& shell, const GpuShadowView& view, float depthBiasTexels) const;

  private:
    struct Locations {
        GLint objectToWorld = -1, worldToObject = -1, distanceScale = -1, clipMin = -1,
              clipMax = -1, clips = -1, viewProjection = -1;
    };
    gl::Program color_;
    gl::Program depth_;
    Locations colorAt_, depthAt_;
    GLint inverseViewProjection_ = -1, depthBias_ = -1, perspective_ = -1;

    static Locations locate(const gl::Program& program);
    static void setShell(const Locations& at, const GpuShell& shell);
};

} // namespace rmsc
