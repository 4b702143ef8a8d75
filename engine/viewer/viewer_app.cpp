// `rmsc view`: the frame loop, the scene and shader files (see viewer_app.hpp); the GPU side is
// view_renderer.hpp.
#include "viewer_app.hpp"
#include "editor/recovery.hpp"
#include "screenshots.hpp"

#include "core/exit_code.hpp"
#include "editor/editing_map.hpp"
#include "editor/scene_edits.hpp"
#include "render/shader_library.hpp"
#include "scene/scene_json.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace rmsc::app {
Viewer::Viewer(const ViewerOptions& opts, std::unique_ptr<Window> win)
    : options(opts), window(std::move(win)), start_(std::chrono::steady_clock::now()) {
    adaptive.targetMilliseconds = options.targetMilliseconds;
    const std::filesystem::path& path = options.scene;
    Diagnostics diagnostics;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (path.empty()) {
        std::optional<Scene> demo = loadScene(kDemoScenePath, embeddedFileSource(), diagnostics);
        document.reset(demo ? *demo : editor::emptyScene(), {});
    } else if (extension == ".gltf" || extension == ".glb") {
        std::optional<PreparedScene> opened = openScene(path, diagnostics);
        if (opened) {
            // The model becomes a mesh instance of a new scene, saved wherever the user says.
            opened->scene.meshes[0].path = std::filesystem::absolute(path);
            document.reset(opened->scene, {});
        }
    } else {
        std::optional<Scene> scene = editor::loadSceneForEditing(path, diagnostics);
        if (scene) document.reset(*scene, path);
        sceneWatcher = editor::FileWatcher(path); // a broken file that gets fixed loads then
    }
    offeredRecovery = editor::findRecovery(document.file());
    if (diagnostics.hasErrors()) {
        openError = "Could not open " + path.string() + "; showing an empty scene.\n" +
                    diagnostics.format();
        std::fputs(diagnostics.format().c_str(), stderr);
    }
    sceneCameraBase = document.scene().camera;
    camera.setFromCamera(sceneCameraBase);
}

Viewer::~Viewer() = default;

double Viewer::now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Viewer::notice(const std::string& text) {
    std::fprintf(stderr, "rmsc view: %s\n", text.c_str());
    notices.emplace_back(text, now());
    while (notices.size() > 6)
        notices.pop_front();
}

bool Viewer::loadShaders(bool initial) {
    ShaderFiles files = embeddedShaderFiles();
#ifdef RMSC_SOURCE_DIR
    const std::filesystem::path sourceShaders = std::filesystem::path(RMSC_SOURCE_DIR) / "shaders";
    std::error_code ec;
    if (options.watchShaders && std::filesystem::is_directory(sourceShaders, ec)) {
        files.overrideDirectory = sourceShaders.string();
        if (initial) shaderWatcher = editor::FileWatcher(sourceShaders);
    }
#endif
    std::string error;
    if (gpu.useShaders(files, error)) {
        if (!initial) notice("shaders reloaded");
        shaderError.clear();
        return true;
    }
    shaderError = "Shader error (the previous shaders stay in use):\n" + error;
    std::fprintf(stderr, "rmsc view: %s\n", shaderError.c_str());
    // The shaders on disk are broken: start with the embedded ones.
    if (initial && !files.overrideDirectory.empty() && gpu.useShaders(embeddedShaderFiles(), error))
        return true;
    return gpu.hasShaders();
}

ViewInput Viewer::viewInput() const {
    ViewInput view;
    view.camera = viewCamera();
    view.scene = &document.scene();
    view.revision = document.revision();
    view.selected = editor::objectIdRange(document.scene(), document.selection);
    view.mode = viewMode;
    return view;
}

void Viewer::renderView() {
    int ww = 0, wh = 0, fw = 0, fh = 0;
    window->windowSize(ww, wh);
    window->framebufferSize(fw, fh);
    gpu.render(viewInput(), viewportPixels(layout.viewport, ww, wh, fw, fh), adaptive);
}

void Viewer::screenshotToDefaultFile() {
    const std::filesystem::path path = defaultScreenshotPath(document.file());
    std::string error;
    if (writeViewShot(gpu, viewInput(), layout.viewport, *window, path.string(), error))
        notice("screenshot written: " + path.string());
    else
        fileError = "Screenshot failed: " + error;
}

void Viewer::autosave() {
    const double t = now();
    if (!document.dirty() || document.revision() == recoveryRevision || t - lastRecoveryWrite < 5.0)
        return;
    lastRecoveryWrite = t;
    std::string error;
    if (editor::writeRecovery(document, error)) {
        recoveryRevision = document.revision();
    } else if (recoveryRevision != document.revision()) {
        notice("cannot write the recovery file: " + error);
        recoveryRevision = document.revision(); // say it once per change, not every 5 s
    }
}

void Viewer::pollFiles() {
    const double t = now();
    if (t - lastPoll < 1.0) return;
    lastPoll = t;
    autosave();
    if (!sceneWatcher.path().empty() && sceneWatcher.changed()) {
        Diagnostics diagnostics;
        std::optional<Scene> scene = editor::loadSceneForEditing(sceneWatcher.path(), diagnostics);
        if (!scene) {
            sceneError = "Reloading " + sceneWatcher.path().string() +
                         " failed (the last good scene stays):\n" + diagnostics.format();
        } else if (document.file() != sceneWatcher.path()) {
            document.reset(*scene, sceneWatcher.path()); // the file failed to open at start
            sceneError.clear();
            openError.clear();
            sceneCameraBase = document.scene().camera;
            camera.setFromCamera(sceneCameraBase);
            notice("opened " + sceneWatcher.path().string());
        } else if (document.dirty()) {
            externalChangePending = true; // ask: reload and lose edits, or keep them
        } else {
            document.reloadFromDisk(*scene);
            sceneError.clear();
            notice("reloaded " + sceneWatcher.path().string() + " (changed on disk)");
        }
    }
    if (!shaderWatcher.path().empty() && shaderWatcher.changed()) loadShaders(false);
}

void Viewer::openFile(const std::filesystem::path& path) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = editor::loadSceneForEditing(path, diagnostics);
    if (!scene) {
        fileError = "Could not open " + path.string() + " (the current scene stays):\n" +
                    diagnostics.format();
        return;
    }
    document.reset(*scene, path);
    sceneWatcher = editor::FileWatcher(path);
    sceneCameraBase = document.scene().camera;
    camera.setFromCamera(sceneCameraBase);
    fileError.clear();
    sceneError.clear();
    notice("opened " + path.string());
}

void Viewer::newScene() {
    document.reset(editor::emptyScene(), {});
    sceneWatcher = editor::FileWatcher();
    sceneCameraBase = document.scene().camera;
    camera.setFromCamera(sceneCameraBase);
    sceneError.clear();
}

void Viewer::save() {
    if (document.file().empty()) {
        askPath = true;
        pathPurpose = PathPurpose::SaveAs;
        pathBuffer = "scene.json";
        return;
    }
    saveAs(document.file());
}

void Viewer::saveAs(const std::filesystem::path& path) {
    std::string error;
    const std::filesystem::path previousFile = document.file();
    if (!document.saveAs(path, error)) {
        fileError = "Save failed; your edits are kept in memory.\n" + error;
        return;
    }
    editor::removeRecovery(previousFile); // the edits are safe in the file now
    editor::removeRecovery(path);
    fileError.clear();
    sceneWatcher = editor::FileWatcher(path); // our own write is not an external change
    notice("saved " + path.string());
}

void Viewer::resetCameraToScene() {
    sceneCameraBase = document.scene().camera;
    camera.setFromCamera(sceneCameraBase);
}

void Viewer::saveCameraToScene() {
    const Camera view = viewCamera();
    document.apply("Save camera", [&](Scene& scene, editor::Selection&) { scene.camera = view; });
    sceneCameraBase = view;
}

void Viewer::requestClose() {
    if (document.dirty())
        askClose = true;
    else
        quitNow = true;
}

int Viewer::run() {
    if (!loadShaders(true)) {
        std::fprintf(stderr, "rmsc view: %s\n", shaderError.c_str());
        return kExitSystem;
    }
    if (!script) attachGlfwInput(window->handle(), &input);
    // Scripted runs (tests) never see a recovery prompt, so they replay the same everywhere.
    askRecover = offeredRecovery.has_value() && !script;
    int failures = 0;
    auto previous = std::chrono::steady_clock::now();
    while (!quitNow) {
        const auto frameStart = std::chrono::steady_clock::now();
        input.beginFrame();
        ScriptActions actions;
        if (script) {
            glfwPollEvents();
            actions = playScriptFrame(*script, frameNumber, input);
        } else if (gpu.refined(adaptive) && !ImGui::IsAnyItemActive() && !gesture.active) {
            glfwWaitEventsTimeout(0.25); // idle: wake for input or the file poll
        } else {
            glfwPollEvents();
        }
        input.finishEvents();
        if (window->shouldClose()) {
            window->setShouldClose(false);
            requestClose();
        }
        const auto nowTime = std::chrono::steady_clock::now();
        const float seconds =
            script ? 1.0f / 30.0f
                   : std::min(0.1f, std::chrono::duration<float>(nowTime - previous).count());
        previous = nowTime;

        int ww = 0, wh = 0, fw = 0, fh = 0;
        window->windowSize(ww, wh);
        window->framebufferSize(fw, fh);
        feedImGui(input, ww, wh, fw, fh, seconds);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        layout = layoutPanels(ww, wh, ImGui::GetFrameHeight());

        handleShortcuts();
        startGesture(); // before the camera, so the S of "scale" does not also fly back
        handleCamera(seconds);
        handleViewportMouse();
        updateGesture();
        drawUi();
        if (!ImGui::IsAnyItemActive() && !gesture.active && document.hasPendingChange())
            document.commit();
        if (!editor::selectionValid(document.scene(), document.selection))
            document.selection = editor::Selection::none();
        pollFiles();
        gpu.updateScene(document.scene(), document.revision(), sceneError);
        gpu.chooseSdfMap(document.scene(), document.selection, actions.waitShaders, frameNumber,
                         sceneError);
        renderView();

        ImGui::Render();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        for (const std::string& path : actions.screenshots) {
            std::string error;
            if (!writeViewShot(gpu, viewInput(), layout.viewport, *window, path, error)) {
                std::fprintf(stderr, "rmsc view: screenshot %s: %s\n", path.c_str(), error.c_str());
                ++failures;
            }
        }
        for (const std::string& path : actions.windowShots) {
            std::string error;
            if (!writeWindowShot(*window, path, error)) {
                std::fprintf(stderr, "rmsc view: window-shot %s: %s\n", path.c_str(),
                             error.c_str());
                ++failures;
            }
        }
        if (actions.quit) requestClose();
        window->swapBuffers();
        frameMilliseconds =
            std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - frameStart)
                .count();
        ++frameNumber;
        if (script && !quitNow && frameNumber > script->lastFrame() + 30) {
            std::fprintf(stderr, "rmsc view: the script ended without the viewer quitting%s\n",
                         document.dirty() ? " (unsaved changes)" : "");
            return kExitSystem;
        }
    }
    if (!document.dirty()) editor::removeRecovery(document.file()); // closed cleanly
    return failures ? kExitSystem : kExitOk;
}

int runViewer(const ViewerOptions& options) {
    std::string error;
    std::optional<Script> script;
    if (!options.script.empty()) {
        script = loadScript(options.script, error);
        if (!script) {
            std::fprintf(stderr, "rmsc view: %s\n", error.c_str());
            return kExitUsage;
        }
    }
    std::unique_ptr<Window> window = Window::open(options.width, options.height, "rmsc", error);
    if (!window) {
        std::fprintf(stderr, "rmsc view: %s\n", error.c_str());
        return kExitSystem;
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    setupImGuiInput();
    ImGui_ImplOpenGL3_Init("#version 450 core");
    int code = kExitOk;
    {
        Viewer viewer(options, std::move(window));
        viewer.script = std::move(script);
        code = viewer.run();
        ImGui_ImplOpenGL3_Shutdown();
    }
    ImGui::DestroyContext();
    return code;
}

} // namespace rmsc::app
