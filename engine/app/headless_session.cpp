// Shared set-up of the headless commands.
#include "headless_session.hpp"

#include "commands.hpp"
#include "core/limits.hpp"
#include "render/shader_library.hpp"

#include <chrono>
#include <cstdio>

namespace rmsc::app {

bool readFrameOptions(const char* command, const ParsedArgs& args, FrameOptions& options) {
    if (args.has("--size") && !parseSize(args.get("--size", ""), options.width, options.height)) {
        std::fprintf(stderr, "rmsc %s: --size: expected %s, got '%s'\n", command,
                     sizeExpectation().c_str(), args.get("--size", "").c_str());
        return false;
    }
    if (!parseGlBackend(args.get("--backend", "auto"), options.backend)) {
        std::fprintf(stderr, "rmsc %s: --backend: expected auto, egl or osmesa, got '%s'\n",
                     command, args.get("--backend", "").c_str());
        return false;
    }
    const std::string strategy = args.get("--sdf-strategy", "baked");
    if (std::optional<SdfStrategy> parsed = parseSdfStrategy(strategy)) {
        options.strategy = *parsed;
    } else {
        std::fprintf(stderr,
                     "rmsc %s: --sdf-strategy: expected baked, buffer or interpreter, got '%s'\n",
                     command, strategy.c_str());
        return false;
    }
    const std::string shells = args.get("--shells", "scene");
    if (shells == "scene" || shells == "fullscreen") {
        options.shells = shells == "scene" ? ShellMode::AsScene : ShellMode::Fullscreen;
    } else if (shells != "both" || std::string(command) != "bench") {
        std::fprintf(stderr, "rmsc %s: --shells: expected scene or fullscreen%s, got '%s'\n",
                     command, std::string(command) == "bench" ? " or both" : "", shells.c_str());
        return false;
    }
    return true;
}

int openHeadlessSession(const char* command, const std::string& scenePath,
                        const FrameOptions& options, HeadlessSession& session,
                        const std::function<int(PreparedScene&)>& beforeUpload) {
    Diagnostics diagnostics;
    session.prepared = openScene(scenePath, diagnostics, options.shells, options.gltfScene);
    std::fputs(diagnostics.format().c_str(), stderr);
    if (!session.prepared) return kExitBadInput;
    if (beforeUpload)
        if (const int code = beforeUpload(*session.prepared)) return code;

    std::string error;
    session.context = createHeadlessContext(options.backend, false, error);
    if (!session.context) {
        std::fprintf(stderr, "rmsc %s: %s\n", command, error.c_str());
        return kExitSystem;
    }
    const auto start = std::chrono::steady_clock::now();
    session.renderer = Renderer::create(embeddedShaderFiles(), error);
    if (!session.renderer) {
        std::fprintf(stderr, "rmsc %s: %s\n", command, error.c_str());
        return kExitSystem;
    }
    session.gpuScene.emplace(uploadScene(*session.prepared, options.strategy));
    if (!session.renderer->prepare(*session.gpuScene, error)) {
        std::fprintf(stderr, "rmsc %s: %s\n", command, error.c_str());
        return kExitSystem;
    }
    glFinish();
    session.shaderBuildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return kExitOk;
}

} // namespace rmsc::app
