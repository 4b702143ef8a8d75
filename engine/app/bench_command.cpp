// rmsc bench: times frames of a scene and reports medians (wall and per-pass GPU time), the
// shader build time and peak memory. Numbers for tracking, never asserted by tests.
#include "commands.hpp"
#include "headless_session.hpp"
#include "render/readback.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/compiler.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
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
     "baked (default), buffer, interpreter, cells, or all (each in turn, with ratios to baked)"},
    {"--sdf-map", nullptr, "FILE",
     "also time a hand-written SDF map (GLSL defining sdfSceneEmpty, sdfDistance, sdfSurface)"},
    {"--shells", nullptr, "MODE",
     "scene: shells through their proxies; fullscreen: all in the fullscreen pass; both "
     "(default when the scene has shells): each in turn"},
    {"--json", nullptr, nullptr, "print one JSON object instead of text"},
    kSandboxOption,
};

} // namespace

const CommandSpec kBenchSpec = {
    "bench",
    "[SCENE]",
    "time frames of a scene (median, min, max per pass)",
    "rmsc bench [SCENE] [--size WxH] [--frames N] [--warmup N] [--sdf-strategy NAME|all] "
    "[--shells scene|fullscreen|both] [--json] [--sandbox DIR]",
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

// What the options ask for.
struct BenchOptions {
    int frames = 10;
    int warmup = 2;
    bool allStrategies = false; // --sdf-strategy all
    std::string shells;         // --shells: scene, fullscreen or both
    FrameOptions frame;
    std::string scenePath;                 // "" = the built-in demo
    std::optional<std::string> sdfMapPath; // --sdf-map
    bool json = false;
};

// One timed run: a scene drawn by one strategy.
struct Variant {
    std::string name;
    const PreparedScene* prepared;
    SdfStrategy strategy;
    std::string program;  // runs of one program through generated code (or through the
                          // interpreter) evaluate the same primitives
    SdfLiveRange live{};  // objects read from the buffer under Baked (the editor's map)
    bool conePass = true; // off: every pixel marches from the near plane
};

// What runs, and the scenes made for it that the variants point to (so a plan stays where it
// was made).
struct BenchPlan {
    std::optional<PreparedScene> fullscreen; // every node in the fullscreen pass
    std::optional<PreparedScene> unbounded;  // compiled without the bounding hierarchy
    std::optional<PreparedScene> edited;     // after a structural edit
    std::string handWrittenMap;              // the --sdf-map file, as the shader reads it
    std::vector<Variant> variants;
};

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
    // The Cells strategy: the cell hierarchy (sdf/cell_pruning.hpp) and the time to prune it
    // again after one shape moved.
    int cellLevels = 0;
    SdfCellStats cells;
    double repruneMs = 0.0;       // pruning again after a one-shape edit
    double repruneUploadMs = 0.0; // and uploading the cells
    std::size_t repruneCells = 0; // the cells it pruned again
};

// Primitives evaluated per pixel, by program (Variant::program, and whether it skips parts).
using EvaluationCounts = std::vector<std::pair<std::string, double>>;

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

// ---- Options and plan ----

constexpr int kMaxFrames = 100000; // of --frames and of --warmup

// Reads the options; prints the problem and returns false on a bad value.
bool readBenchOptions(const ParsedArgs& args, BenchOptions& options) {
    const std::string framesText = args.get("--frames", std::to_string(options.frames));
    if (!parsePositiveInt(framesText, kMaxFrames, options.frames)) {
        std::fprintf(stderr,
                     "rmsc bench: --frames: expected a whole number of timed frames from 1 to %d "
                     "(at least 1 frame is timed), got '%s'\n",
                     kMaxFrames, framesText.c_str());
        return false;
    }
    const std::string warmupText = args.get("--warmup", std::to_string(options.warmup));
    if (!(warmupText == "0" || parsePositiveInt(warmupText, kMaxFrames, options.warmup))) {
        std::fprintf(stderr,
                     "rmsc bench: --warmup: expected a whole number of untimed frames from 0 to "
                     "%d, got '%s'\n",
                     kMaxFrames, warmupText.c_str());
        return false;
    }
    if (warmupText == "0") options.warmup = 0;

    options.allStrategies = args.get("--sdf-strategy", "") == "all";
    options.shells = args.get("--shells", "both");
    ParsedArgs frameArgs = args; // "all" is bench's own: the frame options take one strategy
    if (options.allStrategies) frameArgs.values.erase("--sdf-strategy");
    if (!readFrameOptions("bench", frameArgs, options.frame)) return false;
    options.scenePath = args.positionals.empty() ? "" : args.positionals[0];
    if (args.has("--sdf-map")) options.sdfMapPath = args.get("--sdf-map", "");
    options.json = args.has("--json");
    return true;
}

// Compiles the SDF tree of `prepared` again, with or without the bounding hierarchy
// (SdfCompileOptions::bounds); false if it does not compile.
bool recompileSdf(PreparedScene& prepared, bool bounds) {
    Diagnostics diagnostics;
    const auto materials = std::uint32_t(prepared.scene.materials.size());
    std::optional<CompiledSdfScene> compiled =
        compileSdfScene(*prepared.scene.sdf, materials, prepared.scene.file.string(), diagnostics,
                        {.bounds = bounds});
    if (compiled) prepared.sdf = std::move(compiled->main);
    return compiled.has_value();
}

// The variants, in the order they run: each shell mode with each strategy (and the hand-written
// map), then with every strategy the default without its cone pass and the editor's programs.
// Runs of one program share its evaluation count.
void listVariants(const BenchOptions& options, const PreparedScene& scene,
                  const std::vector<std::pair<std::string, const PreparedScene*>>& modes,
                  const std::vector<SdfStrategy>& timed, BenchPlan& plan) {
    std::vector<Variant>& variants = plan.variants;
    for (const auto& [modeName, prepared] : modes)
        for (SdfStrategy strategy : timed) {
            const std::string base =
                strategy == kHandWritten
                    ? std::string("hand-written")
                    : std::string(sdfStrategyName(effectiveSdfStrategy(prepared->sdf, strategy)));
            variants.push_back({base + modeName, prepared, strategy,
                                strategy == kHandWritten ? "hand-written" : modeName});
        }
    if (options.allStrategies) {
        // The default without its low-resolution pre-pass: what the cone pass saves.
        const std::string base(
            sdfStrategyName(effectiveSdfStrategy(scene.sdf, SdfStrategy::Baked)));
        variants.push_back(
            {base + ", no cone pass", &scene, SdfStrategy::Baked, "no cone pass", {}, false});
    }
    if (const std::optional<PreparedScene>& unbounded = plan.unbounded) {
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
        if (plan.edited)
            variants.push_back({"interpreter, after a structural edit", &*plan.edited,
                                SdfStrategy::Interpreter, "structural edit"});
    }
}

// Plans the runs of the session's scene: opens it again with every node in the fullscreen pass
// when both shell modes run, reads the --sdf-map file, makes the editor's scenes with every
// strategy, and lists the variants. Returns kExitOk or the exit code of the failure (printed).
int planBench(const BenchOptions& options, const HeadlessSession& session, BenchPlan& plan) {
    const PreparedScene& scene = *session.prepared;
    // The shell modes to run: the scene's, and all-fullscreen too when it has shells.
    std::vector<std::pair<std::string, const PreparedScene*>> modes = {{"", &scene}};
    if (options.shells == "both" && !scene.shells.empty()) {
        Diagnostics diagnostics;
        plan.fullscreen = openScene(options.scenePath, diagnostics, ShellMode::Fullscreen);
        if (!plan.fullscreen) {
            std::fputs(diagnostics.format().c_str(), stderr);
            return kExitBadInput;
        }
        modes[0].first = ", shells";
        modes.emplace_back(", fullscreen", &*plan.fullscreen);
    }

    std::vector<SdfStrategy> timed =
        options.allStrategies
            ? std::vector<SdfStrategy>{SdfStrategy::Baked, SdfStrategy::Buffer,
                                       SdfStrategy::Interpreter, SdfStrategy::Cells}
            : std::vector<SdfStrategy>{options.frame.strategy};
    if (options.sdfMapPath) {
        const std::string& path = *options.sdfMapPath;
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in) {
            std::fprintf(stderr, "rmsc bench: --sdf-map: cannot read '%s'\n", path.c_str());
            return kExitBadInput;
        }
        plan.handWrittenMap = "#line 1\n" + text.str();
        timed.push_back(kHandWritten);
    }
    // With every strategy, the interpreter also runs without the bounding hierarchy
    // (SdfCompileOptions::bounds): the baseline the hierarchy is measured against.
    // And after a structural edit (the last child of the root duplicated), the interpreter
    // draws that tree, with the hierarchy, at once, as the viewer does while generated code for
    // it builds in the background (editor/editing_map.hpp): the row's build time is what the
    // edit compiles.
    if (options.allStrategies && scene.scene.sdf) {
        plan.unbounded = scene;
        recompileSdf(*plan.unbounded, false);
        if (!scene.scene.sdf->children.empty()) {
            plan.edited = scene;
            SdfNode& root = *plan.edited->scene.sdf;
            root.children.push_back(root.children.back());
            if (!recompileSdf(*plan.edited, true)) plan.edited.reset();
        }
    }
    listVariants(options, scene, modes, timed, plan);
    return kExitOk;
}

// ---- One variant's run ----

// The warm-up and the timed frames: their wall times and the passes' GPU times.
void timeFrames(Renderer& renderer, const GpuScene& gpuScene, const Scene& scene,
                FrameTargets& targets, const BenchOptions& options, StrategyRun& run) {
    // The warm-up lasts `warmup` frames and, when there is one, at least kMinWarmupMs: short
    // frames right after a build run beside the driver's own work (writing its shader
    // cache), which made the first strategy of a scene look slower than the same code later.
    constexpr double kMinWarmupMs = 300.0;
    const auto warmupStart = std::chrono::steady_clock::now();
    for (int i = 0; run.wall.size() < std::size_t(options.frames); ++i) {
        const auto start = std::chrono::steady_clock::now();
        renderer.render(gpuScene, scene.camera, scene.render, targets);
        glFinish();
        const double ms = millisecondsSince(start);
        if (i == 0) run.firstFrameMs = ms;
        if (i < options.warmup ||
            (options.warmup > 0 && millisecondsSince(warmupStart) < kMinWarmupMs + ms))
            continue;
        run.wall.push_back(ms);
        const PassTimes times = renderer.lastPassTimes();
        for (std::size_t p = 0; p < times.size(); ++p)
            run.passes[p].push_back(times[p]);
    }
}

// The last frame's marched fragments and march steps per pixel (the cone pass's included).
// Returns the frame's pixel count.
double measureMarch(const Renderer& renderer, const FrameTargets& targets, StrategyRun& run) {
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
    return pixels;
}

// Moves the middle shape of the scene's program by a tenth of its distance scale and prunes the
// grid again from the kept state (sdf/cell_pruning.hpp, repruneSdfCells), then writes what
// changed into the cell buffer of the grid before the edit (render/gpu_scene.hpp,
// updateSdfCells): the time a one-shape edit costs, and the cells it pruned.
struct Reprune {
    double pruneMs = 0.0;
    double uploadMs = 0.0;
    std::size_t cells = 0;
};
Reprune repruneAfterOneShapeEdit(const PreparedScene& prepared) {
    const Aabb content = prepared.scene.sdf ? sdfContentBox(*prepared.scene.sdf) : Aabb{};
    SdfCellStatePtr state;
    SdfCellGrid grid = buildSdfCells(prepared.sdf, content, {}, &state);
    if (!state) return {};
    GpuScene uploaded = uploadScene(prepared, SdfStrategy::Cells, &grid);
    glFinish();
    SdfProgram program = prepared.sdf;
    std::vector<std::size_t> shapes;
    for (std::size_t i = 0; i < program.instructions.size(); ++i)
        if (SdfOpcode(program.instructions[i].opcode) == SdfOpcode::Shape) shapes.push_back(i);
    if (shapes.empty()) return {};
    GpuSdfInstruction& moved = program.instructions[shapes[shapes.size() / 2]];
    moved.worldToLocal[0].w += 0.1f * moved.misc.x;
    Reprune result;
    const auto start = std::chrono::steady_clock::now();
    if (!repruneSdfCells(*state, program, grid)) return {};
    result.pruneMs = millisecondsSince(start);
    result.cells = grid.stats.prunedCells;
    const auto uploadStart = std::chrono::steady_clock::now();
    updateSdfCells(uploaded, grid);
    glFinish();
    result.uploadMs = millisecondsSince(uploadStart);
    return result;
}

// Times `variant`: builds its shaders, renders the warm-up and timed frames, reads the march
// statistics and counts the primitives evaluated (once per program). False when a shader build
// fails (printed).
bool runVariant(Renderer& renderer, const Variant& variant, const BenchOptions& options,
                const BenchPlan& plan, const Scene& scene, FrameTargets& targets,
                EvaluationCounts& evaluations, StrategyRun& run) {
    const PreparedScene* prepared = variant.prepared;
    const SdfStrategy strategy = variant.strategy;
    renderer.setConePass(variant.conePass);
    // The edit is measured first, on a build and upload of its own that go before the scene's
    // upload: peak memory then holds one drawn scene, not two.
    if (effectiveSdfStrategy(prepared->sdf, strategy) == SdfStrategy::Cells) {
        const Reprune again = repruneAfterOneShapeEdit(*prepared);
        run.repruneMs = again.pruneMs;
        run.repruneUploadMs = again.uploadMs;
        run.repruneCells = again.cells;
    }
    GpuScene gpuScene = uploadScene(*prepared, strategy);
    if (strategy == kHandWritten) gpuScene.sdfMap = plan.handWrittenMap;
    if (gpuScene.sdfCells.id() != 0) {
        run.cellLevels = gpuScene.sdfCellLevels;
        run.cells = gpuScene.sdfCellStats;
    }
    if (variant.live.first <= variant.live.last)
        gpuScene.sdfMap = generateSdfMap(prepared->sdf, strategy, {}, variant.live);
    const auto compileStart = std::chrono::steady_clock::now();
    std::string error;
    if (!renderer.prepare(gpuScene, error)) {
        std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
        return false;
    }
    run.compileMs = millisecondsSince(compileStart);
    timeFrames(renderer, gpuScene, scene, targets, options, run);
    const double pixels = measureMarch(renderer, targets, run);

    // Primitives evaluated per pixel: one frame of the instrumented cone and march pass, once
    // per program. Only the interpreter skips parts by their boxes (sdf/glsl_codegen.hpp).
    const bool skips = strategy != kHandWritten &&
                       effectiveSdfStrategy(prepared->sdf, strategy) == SdfStrategy::Interpreter;
    const bool cells = gpuScene.sdfCells.id() != 0;
    const std::string countKey =
        variant.program + (skips ? ", skipping" : "") + (cells ? ", cells" : "");
    const auto counted = std::find_if(evaluations.begin(), evaluations.end(),
                                      [&](const auto& e) { return e.first == countKey; });
    if (counted != evaluations.end()) {
        run.evaluationsPerPixel = counted->second;
        return true;
    }
    renderer.setCountEvaluations(true);
    if (!renderer.prepare(gpuScene, error)) {
        std::fprintf(stderr, "rmsc bench: %s\n", error.c_str());
        return false;
    }
    renderer.render(gpuScene, scene.camera, scene.render, targets);
    run.evaluationsPerPixel = double(renderer.lastMarchStatistics().evaluations) / pixels;
    renderer.setCountEvaluations(false);
    evaluations.emplace_back(countKey, run.evaluationsPerPixel);
    return true;
}

// ---- Report ----

double peakResidentMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;
}

std::string sceneName(const BenchOptions& options) {
    return options.scenePath.empty() ? "(built-in demo)" : options.scenePath;
}

void printJson(const BenchOptions& options, const HeadlessContext& context, double peakMiB,
               const std::vector<StrategyRun>& runs) {
    const double firstMedian = stats(runs.front().wall).median;
    std::printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"frames\": %d, "
                "\"renderer\": \"%s\", \"peak_rss_mib\": %.1f, \"strategies\": [",
                sceneName(options).c_str(), options.frame.width, options.frame.height,
                options.frames, context.renderer().c_str(), peakMiB);
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
                    wallStats.median, wallStats.min, wallStats.max, wallStats.median / firstMedian,
                    run.stepsPerPixel, run.coneStepsPerPixel, run.evaluationsPerPixel,
                    (unsigned long long)run.marched.fullscreen,
                    (unsigned long long)run.marched.shells);
        for (std::size_t p = 0; p < run.passes.size(); ++p) {
            const Stats s = stats(run.passes[p]);
            std::printf("%s\"%s\": {\"median\": %.3f, \"min\": %.3f, \"max\": %.3f}", p ? ", " : "",
                        kPassNames[p], s.median, s.min, s.max);
        }
        std::printf("}");
        if (run.cellLevels > 0) {
            const SdfCellStats& c = run.cells;
            std::printf(", \"cells\": {\"levels\": %d, \"per_level\": [", run.cellLevels);
            for (std::size_t l = 0; l < c.cellsPerLevel.size(); ++l)
                std::printf("%s%d", l ? ", " : "", c.cellsPerLevel[l]);
            std::printf("], \"leaf_cells\": %d, \"affine_cells\": %d, \"programs\": %zu, "
                        "\"mean_length\": %.2f, \"mean_instructions\": %.2f, "
                        "\"max_length\": %d, \"max_stack\": %d, \"mean_shapes\": %.2f, "
                        "\"prune_ms\": %.1f, "
                        "\"reprune_one_shape_ms\": %.1f, \"reprune_upload_ms\": %.1f, "
                        "\"reprune_cells\": %zu, \"gpu_bytes\": %zu}",
                        c.leafCells, c.affineCells, c.uniquePrograms, c.meanLength,
                        c.meanInstructions, c.maxLength, c.maxStack, c.meanLeaves, c.buildMs,
                        run.repruneMs, run.repruneUploadMs, run.repruneCells, c.bytes);
        }
        std::printf("}");
    }
    std::printf("]}\n");
}

void printText(const BenchOptions& options, const HeadlessContext& context, double peakMiB,
               const std::vector<StrategyRun>& runs) {
    const double firstMedian = stats(runs.front().wall).median;
    std::printf("scene     %s\nsize      %dx%d, %d frames after %d warm-up\nrenderer  %s (%s)\n",
                sceneName(options).c_str(), options.frame.width, options.frame.height,
                options.frames, options.warmup, context.renderer().c_str(),
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
            std::printf(", %.2fx the %s frame time", wallStats.median / firstMedian,
                        runs.front().name.c_str());
        if (run.cellLevels > 0) {
            const SdfCellStats& c = run.cells;
            std::printf("\ncells     %d levels, cells per level", run.cellLevels);
            for (int n : c.cellsPerLevel)
                std::printf(" %d", n);
            std::printf("; %d leaf cells (%d of them a plane or a constant), %zu distinct "
                        "programs; a cell's list is %.1f steps (%.1f instructions, %.1f shapes) on "
                        "average, %d steps and a value stack %d deep at most; "
                        "pruned in %.1f ms, again after a one-shape edit in %.1f ms (%zu cells) "
                        "and uploaded in %.1f ms; %.2f MiB on the GPU",
                        c.leafCells, c.affineCells, c.uniquePrograms, c.meanLength,
                        c.meanInstructions, c.meanLeaves, c.maxLength, c.maxStack, c.buildMs,
                        run.repruneMs, run.repruneCells, run.repruneUploadMs,
                        double(c.bytes) / (1024.0 * 1024.0));
        }
        std::printf("\n%-9s %9s %9s %9s\n", "ms", "median", "min", "max");
        std::printf("%-9s %9.2f %9.2f %9.2f\n", "frame", wallStats.median, wallStats.min,
                    wallStats.max);
        for (std::size_t p = 0; p < run.passes.size(); ++p) {
            const Stats s = stats(run.passes[p]);
            std::printf("%-9s %9.2f %9.2f %9.2f\n", kPassNames[p], s.median, s.min, s.max);
        }
    }
}

} // namespace

int runBench(const ParsedArgs& args) {
    BenchOptions options;
    if (!readBenchOptions(args, options)) return kExitUsage;
    HeadlessSession session;
    if (const int code = openHeadlessSession("bench", options.scenePath, options.frame, session))
        return code;
    BenchPlan plan;
    if (const int code = planBench(options, session, plan)) return code;
    // Each variant uploads the scene itself: the session's upload goes, so that a large scene's
    // buffers are held once (the peak memory reported is what one drawn scene costs).
    session.gpuScene.reset();
    // So does the grid the cost check pruned (prepare/sdf_cost.hpp): a cells variant measures
    // the edit on a grid of its own before it uploads, and the two grids were held together.
    session.prepared->sdfCells.reset();

    FrameTargets targets = createFrameTargets(options.frame.width, options.frame.height);
    std::vector<StrategyRun> runs;
    EvaluationCounts evaluations;
    for (const Variant& variant : plan.variants) {
        if (std::any_of(runs.begin(), runs.end(),
                        [&](const StrategyRun& r) { return r.name == variant.name; }))
            continue; // a scene too large for generated code runs the interpreter only once
        StrategyRun run;
        run.name = variant.name;
        if (!runVariant(*session.renderer, variant, options, plan, session.prepared->scene, targets,
                        evaluations, run))
            return kExitSystem;
        // The session built the first run's shaders (the scene's strategy): that build's time.
        if (runs.empty() && variant.strategy == options.frame.strategy)
            run.compileMs = session.shaderBuildMs;
        runs.push_back(std::move(run));
    }
    session.renderer->setConePass(true);

    const double peakMiB = peakResidentMiB();
    if (options.json)
        printJson(options, *session.context, peakMiB, runs);
    else
        printText(options, *session.context, peakMiB, runs);
    return kExitOk;
}

} // namespace rmsc::app
