// The frame: shadow pass -> raster pass -> cone pass -> march pass -> (grid pass) -> post pass,
// with the per-frame uniform block and per-pass GPU timers. Owns the passes (the programs), not the
// scene or the targets.
#pragma once

#include "render/cone_pass.hpp"
#include "render/frame.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/grid_pass.hpp"
#include "render/host_pass.hpp"
#include "render/march_pass.hpp"
#include "render/post_pass.hpp"
#include "render/raster_pass.hpp"
#include "render/shadow_pass.hpp"
#include "render/shell_pass.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace rmsc {

// Everything one frame renders into, sized together.
struct FrameTargets {
    GBuffer raster;        // meshes only
    GBuffer combined;      // meshes and SDF: what the AOVs read
    ConeTarget cone;       // per tile of pixels: where their marches start
    DisplayTarget display; // tone-mapped 8-bit sRGB
};

FrameTargets createFrameTargets(int width, int height);

// Rows of a frame to render, counted from the bottom, for rendering one frame in parts (the
// viewer's progressive refinement): [begin, end) go through every pass but the post pass,
// [postBegin, postEnd) through the post pass; `begin` and `end` on multiples of the cone
// pass's tile size (kConeTileSize) unless `end` is the frame's height. Rows outside keep what
// they held. The shadow maps are drawn whole, unless `keepShadowMaps`: the caller knows the
// last render of this renderer drew them for the same scene (they depend on the scene alone:
// its casters and lights, not the camera), so a band of a refinement does not draw them again.
struct RenderRows {
    int begin = 0, end = 0;
    int postBegin = 0, postEnd = 0;
    bool keepShadowMaps = false;
};

enum class Pass { Raster, March, Post, Shadow, Shell, Cone, Grid, Blend, Count };
// Names of the passes, in Pass order (what `rmsc bench` prints).
constexpr std::array<const char*, std::size_t(Pass::Count)> kPassNames = {
    "raster", "march", "post", "shadow", "shell", "cone", "grid", "blend"};

// Fragments whose march took at least one step in the last frame, per pass.
struct MarchStatistics {
    std::uint64_t fullscreen = 0; // the march pass (every pixel may march)
    std::uint64_t shells = 0;     // the shell pass (only the pixels the proxies cover)
    // Primitives evaluated by the cone pass and the march pass (marching, normal, shading,
    // shadows, AO), when the renderer counts them (Renderer::setCountEvaluations), else 0.
    std::uint64_t evaluations = 0;
};

// GPU milliseconds of each pass in the last frame (timer queries).
using PassTimes = std::array<double, std::size_t(Pass::Count)>;

// The passes whose shaders include the scene's SDF map (generated/sdf_map.glsl).
struct SdfPasses {
    ShadingCode shading; // what they are built with
    RasterPass raster;   // marches shadow rays and AO through the SDF
    ConePass cone;
    MarchPass march;
    std::optional<ConePass> countingCone; // the instrumented variants, built when asked for
    std::optional<MarchPass> countingMarch;
    std::uint64_t lastUse = 0; // Renderer::useClock_ when last prepared
};

// The key of the programs built with shading code `shading` ("generated/shading.glsl",
// render/shading_code.hpp) and SDF map `sdfMap` ("generated/sdf_map.glsl"): their texts.
std::string sdfProgramsKey(const ShadingCode& shading, const std::string& sdfMap);

class Renderer {
  public:
    // Builds the passes that do not depend on the scene; the SDF passes are built per map.
    static std::optional<Renderer> create(ShaderFiles files, std::string& error);

    // Makes the programs for the scene's SDF map and its shading (GpuScene::shading) ready: from
    // the cache (keyed by their text, sdfProgramsKey, so scenes of one structure share them) or
    // compiled now. False with the compile log in `error` when the shaders do not build.
    bool prepare(const GpuScene& scene, std::string& error) {
        return prepare(scene, scene.shading, error);
    }
    // Are the programs of this shading code and SDF map (GpuScene::shading and sdfMap) built,
    // so prepare() compiles nothing for them (shells aside)?
    bool hasPrograms(const ShadingCode& shading, const std::string& sdfMap) const {
        return sdfPasses_.contains(sdfProgramsKey(shading, sdfMap));
    }
    // Milliseconds the last prepare() spent compiling and linking (0 on a cache hit).
    double lastCompileMs() const { return lastCompileMs_; }
    // Deletes the programs built for SDF maps and shells (the driver's machine code with them);
    // the next prepare() builds them again.
    void forgetScenePrograms();

    // Renders one frame, or only `rows` of it; prepares the scene first (throws
    // std::runtime_error if its shaders do not build, which is a bug in rmsc, not in the scene).
    void render(const GpuScene& scene, const Camera& camera, const RenderSettings& settings,
                FrameTargets& targets, const RenderRows* rows = nullptr);
    // Draws the scene's SDF objects into a host program's framebuffer (render/host_pass.hpp)
    // through the host's camera (render/host_camera.hpp): the shadow, cone and march passes
    // over the host's depth instead of the raster and shell passes, then the hits into the
    // host's colour and depth. The scene's glTF meshes cast shadows but are not drawn (the host
    // draws its own), nor are the blend, grid and post passes run. `targets` are the viewport's
    // size. Throws std::runtime_error as render() does.
    void renderOverHost(const GpuScene& scene, const FrameCamera& camera, bool zeroToOneDepth,
                        const RenderSettings& settings, FrameTargets& targets,
                        const HostTarget& host);
    // Waits for the last frame and returns its pass times.
    PassTimes lastPassTimes() const;
    // Waits for the last frame and returns how many fragments marched.
    MarchStatistics lastMarchStatistics() const;
    // Draw with the instrumented cone and march pass, which count the primitives every pixel
    // evaluates (slower; for benchmarks). Its programs are built and cached beside the normal ones.
    void setCountEvaluations(bool on) { countEvaluations_ = on; }
    // Run the cone pass before the march pass (the default). Off, every pixel marches from the
    // near plane: the baseline `rmsc bench` measures the pre-pass against.
    void setConePass(bool on) { conePass_ = on; }
    // Draw the ground grid (render/grid_pass.hpp) after the march pass; off by default, the
    // viewer turns it on.
    void setGroundGrid(bool on) { groundGrid_ = on; }

  private:
    // prepare() for the shading code `shading`: a frame's settings may ask for other code than
    // the scene's own.
    bool prepare(const GpuScene& scene, const ShadingCode& shading, std::string& error);
    // The shading code a frame that needs `needed` is drawn with: that, or where its programs are
    // not built, code already built for the scene's map that holds more (the frame's uniforms
    // turn off what it holds beyond, and the picture is the same), so a frame whose settings
    // turn shadows or occlusion off does not wait for a compile.
    ShadingCode drawnShading(const GpuScene& scene, const ShadingCode& needed) const;
    // What both kinds of frame do first: prepare, the frame UBO, the buffers and the shadow
    // pass. Returns the scene's SDF passes and its shells' passes.
    const SdfPasses& beginFrame(const GpuScene& scene, const FrameCamera& frameCamera,
                                bool zeroToOneDepth, const RenderSettings& settings, int width,
                                int height, std::vector<const ShellPass*>& shells,
                                bool drawShadowMaps = true);
    void endFrame() const;

    ShaderFiles files_;
    std::map<std::string, SdfPasses, std::less<>> sdfPasses_; // by sdfProgramsKey
    struct CachedShellPass {
        ShellPass pass;
        std::uint64_t lastUse = 0; // useClock_ when a scene last needed it
    };
    std::map<std::string, CachedShellPass, std::less<>> shellPasses_; // by scene + shell map
    std::uint64_t useClock_ = 0;
    double lastCompileMs_ = 0.0;
    bool countEvaluations_ = false;
    bool conePass_ = true;
    bool groundGrid_ = false;
    PostPass post_;
    GridPass grid_;
    ShadowPass shadow_;
    HostPass host_;
    gl::Buffer frameBuffer_; // GpuFrame uniform block
    gl::Buffer statistics_;  // four uints: MarchStatistics (evaluations in two words)
    std::array<gl::Query, std::size_t(Pass::Count)> timers_;

    Renderer(ShaderFiles files, PostPass post, ShadowPass shadow, GridPass grid, HostPass host);
};

} // namespace rmsc
