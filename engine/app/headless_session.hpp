// What `rmsc render` and `rmsc bench` share: the common options (size, backend) and opening a
// scene with a headless context, a renderer and the scene on the GPU, reporting any failure
// with the right exit code.
#pragma once

#include "gl/context.hpp"
#include "options.hpp"
#include "prepare/prepared_scene.hpp"
#include "render/renderer.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace rmsc::app {

struct FrameOptions {
    int width = 640;
    int height = 360;
    GlBackend backend = GlBackend::Auto;
    SdfStrategy strategy = SdfStrategy::Baked;
    ShellMode shells = ShellMode::AsScene;
    int gltfScene = -1; // --scene of a .gltf/.glb file, -1 for its default scene
};

// Reads --size, --backend, --sdf-strategy and --shells; prints the problem and returns false on a
// bad value.
bool readFrameOptions(const char* command, const ParsedArgs& args, FrameOptions& options);

struct HeadlessSession {
    std::optional<PreparedScene> prepared;
    std::unique_ptr<HeadlessContext> context;
    std::optional<Renderer> renderer;
    std::optional<GpuScene> gpuScene;
    double shaderBuildMs = 0.0; // time to build the renderer's programs for the scene
};

// Opens `scenePath` ("" = the built-in demo), prints diagnostics, lets `beforeUpload` change
// the prepared scene (a pose, a camera; it returns kExitOk or an exit code after printing why),
// creates the context and the renderer and uploads the scene. Returns kExitOk or the exit code
// of the failure.
int openHeadlessSession(const char* command, const std::string& scenePath,
                        const FrameOptions& options, HeadlessSession& session,
                        const std::function<int(PreparedScene&)>& beforeUpload = {});

} // namespace rmsc::app
