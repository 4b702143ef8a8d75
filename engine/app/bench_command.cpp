// rmsc bench: times frames of a scene and reports medians (wall and per-pass GPU time), the
// shader build time and peak memory. Numbers for tracking, never asserted by tests.
#include "commands.hpp"
#include "headless_session.hpp"
#include "render/readback.hpp"
#include "sdf/compiler.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--size", nullptr, "WxH", "frame size (default 640x360)"},
    {"--frames", nullptr, "N", "timed frames (default 10)"},
    {"--warmup", nullptr, "N", "untimed frames first, lasting at least 300 ms (default 2)"},
    {"--backend", nullptr, "NAME", "auto | egl | osmesa"},
    {"--sdf-strategy", nullptr, "NAME",
     "baked (default), buffer, interpreter, or all (each in turn, with ratios to baked)"},
    {"--sdf-map", nullptr, "FILE",
     "also time a hand-written SDF map (GLSL defining sdfSceneEmpty, sdfDistance, sdfSurface)"},
    {"--shells", nullptr, "MODE",
     "scene: shells through their proxies; fullscreen: all in the fullscreen pass; both "
     "(default when the scene has shells): each in turn"},
    {"--json", nullptr, nullptr, "print one JSON object instead of text"},
};

} // namespace

const CommandSpec kBenchSpec = {
    "bench",
    "[SCENE]",
    "time frames of a scene (median, min, max per pass)",
    "rmsc bench [SCENE] [--size WxH] [--frames N] [--warmup N] [--sdf-strategy NAME|all] "
    "[--shells scene|fullscreen|both] [--json]",
    "Renders SCENE (default: the built-in demo) repeatedly and reports, over the timed frames,\n"
    "the median, minimum and maximum of the wall time per frame (glFinish after each) and of\n"
    "each pass's GPU time (timer queries), the time to compile the scene's shaders and the\n"
    "peak resident memory, the SDF march steps per pixel (the cone pre-pass's included) and how\n"
    "many fragments marched in the fullscreen and the shell pass, and the primitives evaluated\n"
    "per pixel (one frame of the instrumented cone and march pass). With --sdf-strategy all,\n"
    "every strategy runs in turn in the same process, the default also without the cone\n"
    "pre-pass, the interpreter also without the bounding hierarchy, and the ratios of their\n"
    "median frame times to the first are reported; a scene with shells also runs with every\n"
    "node in the fullscreen pass (--shells both).",
    kOptions,
    1};

namespace {

// Not a strategy: the run of the --sdf-map file.
constexpr SdfStrategy kHandWritten = SdfStrategy(-1);

// One strategy's timings.
struct StrategyRun {
    std::string name;
    double compileMs = 0.0;
    double firstFrameMs = 0.0;        // the first frame, where drivers finish their programs
    double stepsPerPixel = 0.0;       // mean SDF march steps per pixel of the last frame
    double coneStepsPerPixel = 0.0;   // the cone pass's part of them
    MarchStatistics marched;          // fragments that marched in the last frame
    double evaluationsPerPixel = 0.0; // the cone and march pass's, per pixel
    std::vector<double> wall;
    std::array<std::vector<double>, std::size_t(Pass::Count)> passes;
};

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

int runBench(const ParsedArgs& args) {
    int frames = 10, warmup = 2;
    const std::string warmupText = args.get("--warmup", "2");
    if ((args.has("--frames") && !parsePositiveInt(args.get("--frames", ""), 100000, frames)) ||
        !(warmupText == "0" || parsePositiveInt(warmupText, 100000, warmup))) {
        std::fprintf(stderr, "rmsc bench: --frames and --warmup take whole numbers (warm-up may "
                             "be 0)\n");
        return kExitUsage;
    }
    if (warmupText == "0") warmup = 0;

    const bool all = args.get("--sdf-strategy", "") == "all";
    const std::string shellsOption = args.get("--shells", "both");
    FrameOptions frame;
    ParsedArgs frameArgs = args; // "all" is bench's own: the frame options read one strategy
    if (all) frameArgs.values.erase("--sdf-strategy");
    if (!readFrameOptions("bench", frameArgs, frame)) return kExitUsage;

    HeadlessSession session;
    const std::string scenePath = args.positionals.empty() ? "" : args.positionals[0];
    if (const int code = openHeadlessSession("bench", scenePath, frame, session)) return code;
    Renderer& renderer = *session.renderer;
    FrameTargets targets = createFrameTargets(frame.width, frame.height);
    const Scene& scene = session.prepared->scene;
    // The shell modes to run: the scene's, and all-fullscreen too when it has shells.
    std::vector<std::pair<std::string, const PreparedScene*>> modes = {{"", &*session.prepared}};
    std::optional<PreparedScene> fullscreen;
    if (shellsOption == "both" && !session.prepared->shells.empty()) {
        Diagnostics diagnostics;
        fullscreen = openScene(scenePath, diagnostics, ShellMode::Fullscreen);
        if (!fullscreen) {
            std::fputs(diagnostics.format().c_str(), stderr);
            return kExitBadInput;
        }
        modes[0].first = ", shells";
        modes.emplace_back(", fullscreen", &*fullscreen);
    }

    std::vector<StrategyRun> runs;
    std::vector<std::pair<std::string, double>> evaluations; // per program: primitives / pixel
    const std::vector<SdfStrategy> strategies =
        all ? std::vector<SdfStrategy>{SdfStrategy::Baked, SdfStrategy::Buffer,
                                       SdfStrategy::Interpreter}
            : std::vector<SdfStrategy>{frame.strategy};
    std::vector<SdfStrategy> timed = strategies;
    std::string handWrittenMap;
    if (args.has("--sdf-map")) {
        const std::string path = args.get("--sdf-map", "");
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in) {
            std::fprintf(stderr, "rmsc bench: --sdf-map: cannot read '%s'\n", path.c_str());
            return kExitBadInput;
        }
        handWrittenMap = "#line 1\n" + text.str();
        timed.push_back(kHandWritten);
    }
    // With every strategy, the interpreter also runs without the bounding hierarchy
    // (SdfCompileOptions::bounds): the baseline the hierarchy is measured against.
    // And after a structural edit (the last child of the root duplicated), the interpreter
    // draws that tree, with the hierarchy, at once, as the viewer does while generated code for
    // it builds in the background (editor/editing_map.hpp): the row's build time is what the
    // edit compiles.
    std::optional<PreparedScene> unbounded, edited;
    auto compileSdf = [](PreparedScene& prepared, bool bounds) {
        Diagnostics diagnostics;
        const auto materials = std::uint32_t(prepared.scene.materials.size());
        std::optional<CompiledSdfScene> compiled =
            compileSdfScene(*prepared.scene.sdf, materials, prepared.scene.file.string(),
                            diagnostics, {.bounds = bounds});
        if (compiled) prepared.sdf = std::move(compiled->main);
        return compiled.has_value();
    };
    if (all && session.prepared->scene.sdf) {
        unbounded = *session.prepared;
        compileSdf(*unbounded, false);
        if (!session.prepared->scene.sdf->children.empty()) {
            edited = *session.prepared;
            SdfNode& root = *edited->scene.sdf;
            root.children.push_back(root.children.back());
            if (!compileSdf(*edited, true)) edited.reset();
        }
    }

    // What runs: each shell mode with each strategy (and the hand-written map), then the
    // unbounded interpreter. Runs of one program share its evaluation count.
    struct Variant {
        std::string name;
        const PreparedScene* prepared;
        SdfStrategy strategy;
        std::string program;  // runs of one program through generated code (or through the
                              // interpreter) evaluate the same primitives
        SdfLiveRange live{};  // objects read from the buffer under Baked (the editor's map)
        bool conePass = true; // off: every pixel marches from the near plane
    };
    std::vector<Variant> variants;
    for (const auto& [modeName, prepared] : modes)
        for (SdfStrategy strategy : timed) {
            const std::string base =
                strategy == kHandWritten
                    ? std::string("hand-written")
                    : std::string(sdfStrategyName(effectiveSdfStrategy(prepared->sdf, strategy)));
            variants.push_back({base + modeName, prepared, strategy,
                                strategy == kHandWritten ? "hand-written" : modeName});
        }
    if (all) {
        // The default without its low-resolution pre-pass: what the cone pass saves.
        const std::string base(
            sdfStrategyName(effectiveSdfStrategy(session.prepared->sdf, SdfStrategy::Baked)));
        variants.push_back({base + ", no cone pass",
                            &*session.prepared,
                            SdfStrategy::Baked,
                            "no cone pass",
                            {},
                            false});
    }
    if (unbounded) {
        // What the editor draws while the user drags a shape's parameters: its program (no
        // bounding hierarchy), baked but for the first shape, read from the buffer.
        const auto shape =
            std::find_if(unbounded->sdf.instructions.begin(), unbounded->sdf.instructions.end(),
                         [](const GpuSdfInstruction& in) {
                             return SdfOpcode(in.opcode) == SdfOpcode::Shape ||
                                    SdfOpcode(in.opcode) == SdfOpcode::Profile;
                         });
        if (shape != unbounded->sdf.instructions.end() &&
            effectiveSdfStrategy(unbounded->sdf, SdfStrategy::Baked) == SdfStrategy::Baked)
            variants.push_back({"baked, editing one shape", &*unbounded, SdfStrategy::Baked,
                                "no bounds", SdfLiveRange{shape->objectId, shape->objectId}});
        variants.push_back(
            {"interpreter, no bounds", &*unbounded, SdfStrategy::Interpreter, "no bounds"});
        if (edited)
            variants.push_back({"interpreter, after a structural edit", &*edited,
                                SdfStrategy::Interpreter, "structural edit"});
    }

    for (const Variant& variant : variants) {
        const PreparedScene* prepared = variant.prepared;
        const SdfStrategy strategy = variant.strategy;
        StrategyRun run;
        run.name = variant.name;
        if (std::any_of(runs.begin(), runs.end(),
                        [&](const StrategyRun& r) { return r.name == run.name; }))
            continue; // a scene too large for generated code runs the interpreter only once
        renderer.setConePass(variant.conePass);
        GpuScene gpuScene = uploadScene(*prepared, strategy);
        if (strategy == kHandWritten) gpuScene.sdfMap = handWrittenMap;
        if (variant.live.first <= variant.live.last)
            gpuScene.sdfMap = generateSdfMap(prepared->sdf, strategy, {}, variant.live);
        const auto compileStart = std::chrono::steady_clock::now();
        std::string error;
        if (!renderer.prepare(gpuScene, error)) {
            std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
            return kExitSystem;
        }
        run.compileMs = strategy == frame.strategy && runs.empty()
                            ? session.shaderBuildMs
                            : millisecondsSince(compileStart);
        // The warm-up lasts `warmup` frames and, when there is one, at least kMinWarmupMs: short
        // frames right after a build run beside the driver's own work (writing its shader
        // cache), which made the first strategy of a scene look slower than the same code later.
        constexpr double kMinWarmupMs = 300.0;
        const auto warmupStart = std::chrono::steady_clock::now();
        for (int i = 0; run.wall.size() < std::size_t(frames); ++i) {
            const auto start = std::chrono::steady_clock::now();
            renderer.render(gpuScene, scene.camera, scene.render, targets);
            glFinish();
            const double ms = millisecondsSince(start);
            if (i == 0) run.firstFrameMs = ms;
            if (i < warmup || (warmup > 0 && millisecondsSince(warmupStart) < kMinWarmupMs + ms))
                continue;
            run.wall.push_back(ms);
            const PassTimes times = renderer.lastPassTimes();
            for (std::size_t p = 0; p < times.size(); ++p)
                run.passes[p].push_back(times[p]);
        }
        run.marched = renderer.lastMarchStatistics();
        const Pixels<float> steps = readMarchSteps(targets);
        double total = 0.0, coneTotal = 0.0;
        for (float n : steps.data)
            total += n;
        const Pixels<float> tiles = readConeTiles(targets);
        for (std::size_t i = 1; i < tiles.data.size(); i += 2)
            coneTotal += tiles.data[i];
        const double pixels = double(std::max<std::size_t>(steps.data.size(), 1));
        run.coneStepsPerPixel = coneTotal / pixels;
        run.stepsPerPixel = (total + coneTotal) / pixels;
        // Primitives evaluated per pixel: one frame of the instrumented cone and march pass, once
        // per program. Only the interpreter skips parts by their boxes (sdf/glsl_codegen.hpp).
        const bool skips =
            strategy != kHandWritten &&
            effectiveSdfStrategy(prepared->sdf, strategy) == SdfStrategy::Interpreter;
        const std::string countKey = variant.program + (skips ? ", skipping" : "");
        const auto counted = std::find_if(evaluations.begin(), evaluations.end(),
                                          [&](const auto& e) { return e.first == countKey; });
        if (counted != evaluations.end()) {
            run.evaluationsPerPixel = counted->second;
        } else {
            renderer.setCountEvaluations(true);
            if (!renderer.prepare(gpuScene, error)) {
                std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
                return kExitSystem;
            }
            renderer.render(gpuScene, scene.camera, scene.render, targets);
            run.evaluationsPerPixel = double(renderer.lastMarchStatistics().evaluations) / pixels;
            renderer.setCountEvaluations(false);
            evaluations.emplace_back(countKey, run.evaluationsPerPixel);
        }
        runs.push_back(std::move(run));
    }
    renderer.setConePass(true);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double peakMiB = double(usage.ru_maxrss) / 1024.0;

    const char* passNames[] = {"raster", "march", "post", "shadow", "shell", "cone"};
    static_assert(std::size(passNames) == std::size_t(Pass::Count));
    const std::string name = scenePath.empty() ? "(built-in demo)" : scenePath;
    const HeadlessContext& context = *session.context;
    const double bakedMedian = stats(runs.front().wall).median;
    if (args.has("--json")) {
        std::printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"frames\": %d, "
                    "\"renderer\": \"%s\", \"peak_rss_mib\": %.1f, \"strategies\": [",
                    name.c_str(), frame.width, frame.height, frames, context.renderer().c_str(),
                    peakMiB);
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const StrategyRun& run = runs[r];
            const Stats wallStats = stats(run.wall);
            std::printf("%s{\"strategy\": \"%s\", \"shader_build_ms\": %.3f, "
                        "\"first_frame_ms\": %.3f, \"frame_ms\": {\"median\": %.3f, \"min\": %.3f, "
                        "\"max\": %.3f}, "
                        "\"ratio_to_first\": %.3f, \"march_steps_per_pixel\": %.2f, "
                        "\"cone_steps_per_pixel\": %.3f, "
                        "\"evaluations_per_pixel\": %.1f, "
                        "\"marched_fragments\": {\"fullscreen\": %llu, \"shells\": %llu}, "
                        "\"pass_gpu_ms\": {",
                        r ? ", " : "", run.name.c_str(), run.compileMs, run.firstFrameMs,
                        wallStats.median, wallStats.min, wallStats.max,
                        wallStats.median / bakedMedian, run.stepsPerPixel, run.coneStepsPerPixel,
                        run.evaluationsPerPixel, (unsigned long long)run.marched.fullscreen,
                        (unsigned long long)run.marched.shells);
            for (std::size_t p = 0; p < run.passes.size(); ++p) {
                const Stats s = stats(run.passes[p]);
                std::printf("%s\"%s\": {\"median\": %.3f, \"min\": %.3f, \"max\": %.3f}",
                            p ? ", " : "", passNames[p], s.median, s.min, s.max);
            }
            std::printf("}}");
        }
        std::printf("]}\n");
        return kExitOk;
    }
    std::printf("scene     %s\nsize      %dx%d, %d frames after %d warm-up\nrenderer  %s (%s)\n",
                name.c_str(), frame.width, frame.height, frames, warmup, context.renderer().c_str(),
                std::string(context.backendName()).c_str());
    std::printf("memory    %.1f MiB peak resident\n", peakMiB);
    for (const StrategyRun& run : runs) {
        const Stats wallStats = stats(run.wall);
        std::printf("\nstrategy  %s: shaders %.1f ms to build, %.1f march steps and %.1f "
                    "primitive evaluations per pixel, fragments marched: %llu fullscreen + %llu "
                    "in shells",
                    run.name.c_str(), run.compileMs, run.stepsPerPixel, run.evaluationsPerPixel,
                    (unsigned long long)run.marched.fullscreen,
                    (unsigned long long)run.marched.shells);
        if (runs.size() > 1)
            std::printf(", %.2fx the %s frame time", wallStats.median / bakedMedian,
                        runs.front().name.c_str());
        std::printf("\n%-9s %9s %9s %9s\n", "ms", "median", "min", "max");
        std::printf("%-9s %9.2f %9.2f %9.2f\n", "frame", wallStats.median, wallStats.min,
                    wallStats.max);
        for (std::size_t p = 0; p < run.passes.size(); ++p) {
            const Stats s = stats(run.passes[p]);
            std::printf("%-9s %9.2f %9.2f %9.2f\n", passNames[p], s.median, s.min, s.max);
        }
    }
    return kExitOk;
}

} // namespace rmsc::app
