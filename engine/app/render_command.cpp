// rmsc render: one frame of a scene to an image file (display colour or an AOV).
#include "commands.hpp"
#include "headless_session.hpp"

#include "core/image_io.hpp"
#include "render/readback.hpp"

#include <cstdio>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--output", "-o", "FILE", "image to write (.png; .pfm for float depth/normal)"},
    {"--size", nullptr, "WxH", "image size in pixels (default 640x360)"},
    {"--backend", nullptr, "NAME", "auto | egl | osmesa (default auto: EGL, then OSMesa)"},
    {"--sdf-strategy", nullptr, "NAME",
     "how the SDF scene reaches the shader: baked (default), buffer, interpreter or cells (the program pruned per cell; the default above 160 shapes)"},
    {"--shells", nullptr, "MODE",
     "scene (default): shells through their proxy meshes; fullscreen: every SDF node in the "
     "fullscreen pass"},
    {"--aov", nullptr, "NAME",
     "color | depth | normal | id | steps (default color); depth is linear view depth"},
    kSandboxOption,
};

} // namespace

const CommandSpec kRenderSpec = {
    "render",
    "[SCENE] -o OUT.png",
    "render a scene (or a .gltf/.glb, or the built-in demo) to PNG",
    "rmsc render [SCENE] -o OUT.png [--size WxH] [--backend B] [--aov A] [--sandbox DIR]",
    "Renders SCENE (a .json scene, or a .gltf/.glb model opened with a default light and a\n"
    "framing camera; without SCENE, the built-in demo) headless and writes one image.\n"
    "AOVs: depth = 16-bit grey PNG, round(65535*(z-near)/(far-near)), 65535 where nothing was\n"
    "hit (or float view depth in a .pfm); normal = world normal as (n*0.5+0.5) in RGB, black\n"
    "where nothing was hit (float in a .pfm); id = a stable colour per object; steps = the\n"
    "SDF march steps per pixel as a heatmap, black 0 to red at max_steps (float in a .pfm).",
    kOptions,
    1};

int runRender(const ParsedArgs& args) {
    FrameOptions frame;
    if (!readFrameOptions("render", args, frame)) return kExitUsage;
    const std::string aov = args.get("--aov", "color");
    if (aov != "color" && aov != "depth" && aov != "normal" && aov != "id" && aov != "steps") {
        std::fprintf(stderr,
                     "rmsc render: --aov: expected color, depth, normal, id or steps, got '%s'\n",
                     aov.c_str());
        return kExitUsage;
    }
    const std::filesystem::path output = args.get("--output", "");
    if (output.empty()) {
        std::fprintf(stderr, "rmsc render: no output file given (-o OUT.png)\n");
        return kExitUsage;
    }
    const bool pfm = output.extension() == ".pfm";
    if (output.extension() != ".png" && !pfm) {
        std::fprintf(stderr, "rmsc render: %s: expected a .png or .pfm file name\n",
                     output.c_str());
        return kExitUsage;
    }
    if (pfm && aov != "depth" && aov != "normal" && aov != "steps") {
        std::fprintf(stderr, "rmsc render: .pfm output is for --aov depth, normal or steps\n");
        return kExitUsage;
    }

    HeadlessSession session;
    const std::string scenePath = args.positionals.empty() ? "" : args.positionals[0];
    if (const int code = openHeadlessSession("render", scenePath, frame, session)) return code;
    FrameTargets targets = createFrameTargets(frame.width, frame.height);
    const Scene& scene = session.prepared->scene;
    session.renderer->render(*session.gpuScene, scene.camera, scene.render, targets);

    std::string error;
    bool written = false;
    if (aov == "color") {
        written = writePng8(output, readDisplayColor(targets), error);
    } else if (aov == "depth") {
        const Pixels<float> depth = readViewDepth(targets);
        written =
            pfm ? writePfm(output, depth, error)
                : writePng16(output,
                             encodeDepth16(depth, scene.camera.nearPlane, scene.camera.farPlane),
                             error);
    } else if (aov == "normal") {
        const Pixels<float> normals = readNormals(targets);
        written = pfm ? writePfm(output, normals, error)
                      : writePng8(output, encodeNormals(normals), error);
    } else if (aov == "steps") {
        const Pixels<float> steps = readMarchSteps(targets);
        written = pfm ? writePfm(output, steps, error)
                      : writePng8(output, encodeStepsHeatmap(steps, scene.render.maxSteps), error);
    } else {
        written = writePng8(output, encodeObjectIds(readObjectIds(targets)), error);
    }
    if (!written) {
        std::fprintf(stderr, "rmsc render: %s: cannot write the image: %s\n", output.c_str(),
                     error.c_str());
        return kExitSystem;
    }
    return kExitOk;
}

} // namespace rmsc::app
