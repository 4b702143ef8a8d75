// rmsc render: one frame of a scene to an image file (display colour or an AOV).
#include "commands.hpp"
#include "headless_session.hpp"

#include "core/image_io.hpp"
#include "render/gpu_mesh.hpp"
#include "render/readback.hpp"
#include "render_timing.hpp"

#include <cstdio>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--output", "-o", "FILE", "image to write (.png; .pfm for float depth/normal)"},
    {"--size", nullptr, "WxH", "image size in pixels (default 640x360)"},
    {"--backend", nullptr, "NAME", "auto | egl | osmesa (default auto: EGL, then OSMesa)"},
    {"--sdf-strategy", nullptr, "NAME",
     "how the SDF scene reaches the shader: baked (default), buffer, interpreter or cells (the "
     "program pruned per cell; the default above 160 shapes)"},
    {"--shells", nullptr, "MODE",
     "scene (default): shells through their proxy meshes; fullscreen: every SDF node in the "
     "fullscreen pass"},
    {"--aov", nullptr, "NAME",
     "color | depth | normal | id | steps (default color); depth is linear view depth"},
    {"--time", nullptr, "SECONDS",
     "pose the glTF animations at this time (a .gltf/.glb: --animation, else its first)"},
    {"--animation", nullptr, "NAME|INDEX", "which animation of the .gltf/.glb file to pose"},
    {"--frames", nullptr, "A:B",
     "render frames A to B (at A/fps ... B/fps seconds); -o holds %04d for the frame number"},
    {"--fps", nullptr, "N", "frames a second of --frames (default 24)"},
    {"--camera", nullptr, "N|NAME", "render through a camera of the .gltf/.glb file"},
    {"--scene", nullptr, "N", "the scene of the .gltf/.glb file to draw (default: its own)"},
    kSandboxOption,
};

} // namespace

const CommandSpec kRenderSpec = {
    "render",
    "[SCENE] -o OUT.png",
    "render a scene (or a .gltf/.glb, or the built-in demo) to PNG",
    "rmsc render [SCENE] -o OUT.png [--size WxH] [--backend B] [--aov A] [--time S] "
    "[--animation A] [--frames A:B --fps N] [--camera C] [--scene N] [--sandbox DIR]",
    "Renders SCENE (a .json scene, or a .gltf/.glb model opened with a default light and a\n"
    "framing camera; without SCENE, the built-in demo) headless and writes one image.\n"
    "AOVs: depth = 16-bit grey PNG, round(65535*(z-near)/(far-near)), 65535 where nothing was\n"
    "hit (or float view depth in a .pfm); normal = world normal as (n*0.5+0.5) in RGB, black\n"
    "where nothing was hit (float in a .pfm); id = a stable colour per object; steps = the\n"
    "SDF march steps per pixel as a heatmap, black 0 to red at max_steps (float in a .pfm).\n"
    "Animation: --time poses a glTF file's animation (or each scene mesh's \"animation\") at a\n"
    "time; --frames A:B --fps N -o out_%04d.png writes frames A to B, each independent of the\n"
    "others, so a sequence can be split across processes. --camera and --scene use the .gltf\n"
    "file's own cameras (perspective only) and scenes.",
    kOptions,
    1};

namespace {

// Renders the session's scene and writes `output` (the AOV asked for); kExitOk or the failure.
int renderOne(HeadlessSession& session, FrameTargets& targets, const std::string& aov, bool pfm,
              const std::filesystem::path& output) {
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

} // namespace

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

    const std::string scenePath = args.positionals.empty() ? "" : args.positionals[0];
    RenderTiming timing;
    if (!readRenderTiming(args, scenePath, timing)) return kExitUsage;
    if (timing.sequence && !isFramePattern(output.string())) {
        std::fprintf(stderr,
                     "rmsc render: --frames: expected -o to hold one %%d or %%04d for the frame "
                     "number, got '%s'\n",
                     output.c_str());
        return kExitUsage;
    }
    frame.gltfScene = timing.scene;

    HeadlessSession session;
    if (const int code =
            openHeadlessSession("render", scenePath, frame, session, [&](PreparedScene& prepared) {
                return applyRenderTiming(timing, prepared);
            }))
        return code;
    FrameTargets targets = createFrameTargets(frame.width, frame.height);
    const int first = timing.sequence ? timing.firstFrame : 0;
    const int last = timing.sequence ? timing.lastFrame : 0;
    for (int f = first; f <= last; ++f) {
        if (timing.sequence && f > first) {
            if (!poseAtTime(timing, timing.frameTime(f), *session.prepared)) return kExitBadInput;
            for (std::size_t a = 0; a < session.prepared->assets.size(); ++a)
                if (a < session.prepared->assetPoses.size() &&
                    session.prepared->assetPoses[a].animation >= 0)
                    updateMeshVertices(session.prepared->assets[a], session.gpuScene->meshes[a]);
        }
        const std::filesystem::path file = timing.sequence ? frameFile(output.string(), f) : output;
        if (const int code = renderOne(session, targets, aov, pfm, file)) return code;
    }
    return kExitOk;
}

} // namespace rmsc::app
