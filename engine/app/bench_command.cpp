// rmsc bench: times frames of a scene and reports medians (wall and per-pass GPU time), the
// shader build time and peak memory. Numbers for tracking, never asserted by tests.
#include "app/commands.hpp"
#include "app/options.hpp"

#include "gl/context.hpp"
#include "render/renderer.hpp"
#include "scene/prepared_scene.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--size", nullptr, "WxH", "frame size (default 640x360)"},
    {"--frames", nullptr, "N", "timed frames (default 10)"},
    {"--warmup", nullptr, "N", "untimed frames first (default 2)"},
    {"--backend", nullptr, "NAME", "auto | egl | osmesa"},
    {"--json", nullptr, nullptr, "print one JSON object instead of text"},
};

const CommandSpec kSpec = {
    "bench", "rmsc bench [SCENE] [--size WxH] [--frames N] [--warmup N] [--json]",
    "Renders SCENE (default: the built-in demo) repeatedly and reports, over the timed frames,\n"
    "the median, minimum and maximum of the wall time per frame (glFinish after each) and of\n"
    "each pass's GPU time (timer queries), the shader build time and the peak resident memory.",
    kOptions, 1};

struct Stats {
    double median = 0, min = 0, max = 0;
};

Stats stats(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

int runBench(std::span<const std::string> args) {
    std::string error;
    std::optional<ParsedArgs> parsed = parseArgs(kSpec, args, error);
    if (!parsed) {
        std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
        return kExitUsage;
    }
    if (parsed->help) {
        std::fputs(formatHelp(kSpec).c_str(), stdout);
        return kExitOk;
    }
    int width = 640, height = 360, frames = 10, warmup = 2;
    GlBackend backend = GlBackend::Auto;
    if ((parsed->has("--size") && !parseSize(parsed->get("--size", ""), width, height)) ||
        (parsed->has("--frames") && !parsePositiveInt(parsed->get("--frames", ""), 100000, frames)) ||
        (parsed->has("--warmup") &&
         !(parsed->get("--warmup", "") == "0" ||
           parsePositiveInt(parsed->get("--warmup", ""), 100000, warmup))) ||
        !parseGlBackend(parsed->get("--backend", "auto"), backend)) {
        std::fprintf(stderr, "rmsc bench: bad option value (see rmsc bench --help)\n");
        return kExitUsage;
    }
    if (parsed->get("--warmup", "") == "0") warmup = 0;

    Diagnostics diagnostics;
    const std::string scenePath = parsed->positionals.empty() ? "" : parsed->positionals[0];
    std::optional<PreparedScene> prepared = openScene(scenePath, diagnostics);
    std::fputs(diagnostics.format().c_str(), stderr);
    if (!prepared) return kExitBadInput;

    std::unique_ptr<HeadlessContext> context = createHeadlessContext(backend, false, error);
    if (!context) {
        std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
        return kExitSystem;
    }
    const auto buildStart = std::chrono::steady_clock::now();
    std::optional<Renderer> renderer = Renderer::create(ShaderFiles::embedded(), error);
    glFinish();
    const double buildMs = millisecondsSince(buildStart);
    if (!renderer) {
        std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
        return kExitSystem;
    }
    const GpuScene gpuScene = uploadScene(*prepared);
    FrameTargets targets = createFrameTargets(width, height);
    const Scene& scene = prepared->scene;

    std::vector<double> wall;
    std::array<std::vector<double>, std::size_t(Pass::Count)> passes;
    for (int i = 0; i < warmup + frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        renderer->render(gpuScene, scene.camera, scene.render, targets);
        glFinish();
        const double ms = millisecondsSince(start);
        if (i < warmup) continue;
        wall.push_back(ms);
        const PassTimes times = renderer->lastPassTimes();
        for (std::size_t p = 0; p < times.size(); ++p) passes[p].push_back(times[p]);
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double peakMiB = double(usage.ru_maxrss) / 1024.0;

    const char* passNames[] = {"raster", "march", "post"};
    const Stats wallStats = stats(wall);
    const std::string name = scenePath.empty() ? "(built-in demo)" : scenePath;
    if (parsed->has("--json")) {
        std::printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"frames\": %d, "
                    "\"renderer\": \"%s\", \"shader_build_ms\": %.3f, \"peak_rss_mib\": %.1f, "
                    "\"frame_ms\": {\"median\": %.3f, \"min\": %.3f, \"max\": %.3f}, "
                    "\"pass_gpu_ms\": {",
                    name.c_str(), width, height, frames, context->renderer().c_str(), buildMs,
                    peakMiB, wallStats.median, wallStats.min, wallStats.max);
        for (std::size_t p = 0; p < passes.size(); ++p) {
            const Stats s = stats(passes[p]);
            std::printf("%s\"%s\": {\"median\": %.3f, \"min\": %.3f, \"max\": %.3f}",
                        p ? ", " : "", passNames[p], s.median, s.min, s.max);
        }
        std::printf("}}\n");
        return kExitOk;
    }
    std::printf("scene     %s\nsize      %dx%d, %d frames after %d warm-up\nrenderer  %s (%s)\n",
                name.c_str(), width, height, frames, warmup, context->renderer().c_str(),
                std::string(context->backendName()).c_str());
    std::printf("shaders   %.1f ms to build\nmemory    %.1f MiB peak resident\n", buildMs,
                peakMiB);
    std::printf("%-9s %9s %9s %9s\n", "ms", "median", "min", "max");
    std::printf("%-9s %9.2f %9.2f %9.2f\n", "frame", wallStats.median, wallStats.min,
                wallStats.max);
    for (std::size_t p = 0; p < passes.size(); ++p) {
        const Stats s = stats(passes[p]);
        std::printf("%-9s %9.2f %9.2f %9.2f\n", passNames[p], s.median, s.min, s.max);
    }
    return kExitOk;
}

} // namespace rmsc::app
