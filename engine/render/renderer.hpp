// The frame: raster pass -> march pass -> post pass, with the per-frame uniform block and
// per-pass GPU timers. Owns the passes (the programs), not the scene or the targets.
#pragma once

#include "render/frame.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/march_pass.hpp"
#include "render/post_pass.hpp"
#include "render/raster_pass.hpp"

#include <array>
#include <optional>
#include <string>

namespace rmsc {

// Everything one frame renders into, sized together.
struct FrameTargets {
    GBuffer raster;        // meshes only
    GBuffer combined;      // meshes and SDF: what the AOVs read
    DisplayTarget display; // tone-mapped 8-bit sRGB
};

FrameTargets createFrameTargets(int width, int height);

enum class Pass { Raster, March, Post, Count };

// GPU milliseconds of each pass in the last frame (timer queries).
using PassTimes = std::array<double, std::size_t(Pass::Count)>;

class Renderer {
public:
    static std::optional<Renderer> create(const ShaderFiles& files, std::string& error);

    void render(const GpuScene& scene, const Camera& camera, const RenderSettings& settings,
                FrameTargets& targets);
    // Waits for the last frame and returns its pass times.
    PassTimes lastPassTimes() const;

private:
    RasterPass raster_;
    MarchPass march_;
    PostPass post_;
    gl::Buffer frameBuffer_; // GpuFrame uniform block
    std::array<gl::Query, std::size_t(Pass::Count)> timers_;

    Renderer(RasterPass raster, MarchPass march, PostPass post);
};

} // namespace rmsc
