// `rmsc view`: the frame loop, the scene and shader files (see viewer_app.hpp); the GPU side is
// view_renderer.hpp.
#include "viewer_app.hpp"
#include "document_edits.hpp"
#include "editor/recovery.hpp"
#include "hierarchy_panel.hpp"
#include "menu_bar.hpp"
#include "overlay.hpp"
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
    view.adaptive.targetMilliseconds = options.targetMilliseconds;
    openStartScene(options.scene, session, files, messages);
    dialogs.offeredRecovery = editor::findRecovery(session.document.file());
}

Viewer::~Viewer() = default;

double Viewer::now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool Viewer::loadShaders(bool initial) {
    ShaderFiles shaders = embeddedShaderFiles();
#ifdef RMSC_SOURCE_DIR
    const std::filesystem::path sourceShaders = std::filesystem::path(RMSC_SOURCE_DIR) / "shaders";
    std::error_code ec;
    if (options.watchShaders && std::filesystem::is_directory(sourceShaders, ec)) {
        shaders.overrideDirectory = sourceShaders.string();
        if (initial) shaderWatcher = editor::FileWatcher(sourceShaders);
    }
#endif
    std::string error;
    if (gpu.useShaders(shaders, error)) {
        if (!initial) messages.notice("shaders reloaded");
        messages.shaderError.clear();
        return true;
    }
    messages.shaderError = "Shader error (the previous shaders stay in use):\n" + error;
    std::fprintf(stderr, "rmsc view: %s\n", messages.shaderError.c_str());
    // The shaders on disk are broken: start with the embedded ones.
    if (initial && !shaders.overrideDirectory.empty() &&
        gpu.useShaders(embeddedShaderFiles(), error))
        return true;
    return gpu.hasShaders();
}

ViewInput Viewer::viewInput() const {
    ViewInput shown;
    shown.camera = session.viewCamera();
    shown.scene = &session.document.scene();
    shown.revision = session.document.revision();
    shown.selected = editor::objectIdRange(session.document.scene(), session.document.selection);
    shown.mode = view.mode;
    return shown;
}

void Viewer::renderView() {
    int ww = 0, wh = 0, fw = 0, fh = 0;
    window->windowSize(ww, wh);
    window->framebufferSize(fw, fh);
    gpu.render(viewInput(), viewportPixels(layout.viewport, ww, wh, fw, fh), view.adaptive);
}

void Viewer::screenshotToDefaultFile() {
    const std::filesystem::path path = defaultScreenshotPath(session.document.file());
    std::string error;
    if (writeViewShot(gpu, viewInput(), layout.viewport, *window, path.string(), error))
        messages.notice("screenshot written: " + path.string());
    else
        messages.fileError = "Screenshot failed: " + error;
}

void Viewer::drawUi() {
    ViewerCommands commands;
    if (ImGui::BeginMainMenuBar()) {
        drawMenus(session.document, view, commands);
        carryOut(commands); // before the title, which shows whether the scene is saved
        drawMenuBarTitle(session.document);
        ImGui::EndMainMenuBar();
    }
    drawHierarchyPanel(session.document, layout, commands);
    carryOut(commands);
    drawInspectorPanel(session, inspector, view, layout, commands);
    carryOut(commands);
    drawStatusOverlay(layout.viewport, gpu.status(), frameMilliseconds, view, session.camera.speed,
                      gesture.active ? &gesture.math : nullptr, messages);
    drawProblems(layout.viewport, messages);
    drawDialogs(dialogs, session, files, messages);
}

void Viewer::carryOut(ViewerCommands& commands) {
    editor::Document& document = session.document;
    for (const ViewerCommand command : commands) {
        switch (command) {
        case ViewerCommand::Undo:
            document.undo();
            break;
        case ViewerCommand::Redo:
            document.redo();
            break;
        case ViewerCommand::Duplicate:
            duplicateSelection(document);
            break;
        case ViewerCommand::Delete:
            deleteSelection(document);
            break;
        case ViewerCommand::NewScene:
            if (document.dirty()) {
                dialogs.askClose = true;
                dialogs.afterDiscard = AfterDiscard::New;
            } else {
                newScene(session, files, messages);
            }
            break;
        case ViewerCommand::Open:
            dialogs.askForPath(PathPurpose::Open, document.file().string());
            break;
        case ViewerCommand::Save:
            saveScene(session, files, messages, dialogs);
            break;
        case ViewerCommand::SaveAs:
            dialogs.askForPath(PathPurpose::SaveAs,
                               document.file().empty() ? "scene.json" : document.file().string());
            break;
        case ViewerCommand::AddMesh:
            dialogs.askForPath(PathPurpose::AddMesh, "");
            break;
        case ViewerCommand::Screenshot:
            screenshotToDefaultFile();
            break;
        case ViewerCommand::Quit:
            dialogs.afterDiscard = AfterDiscard::Quit;
            requestClose(dialogs, document);
            break;
        case ViewerCommand::FrameSelection:
            frameSelection();
            break;
        case ViewerCommand::SaveCamera:
            session.saveCameraToScene();
            break;
        case ViewerCommand::ResetCamera:
            session.resetCamera();
            break;
        }
    }
    commands.clear();
}

void Viewer::pollFiles() {
    const double t = now();
    if (t - lastPoll < 1.0) return;
    lastPoll = t;
    writeRecoveryFile(session.document, files, messages, t);
    if (reloadChangedSceneFile(session, files, messages)) dialogs.askReload = true;
    if (!shaderWatcher.path().empty() && shaderWatcher.changed()) loadShaders(false);
}

int Viewer::run() {
    if (!loadShaders(true)) {
        std::fprintf(stderr, "rmsc view: %s\n", messages.shaderError.c_str());
        return kExitSystem;
    }
    if (!script) attachGlfwInput(window->handle(), &input);
    // Scripted runs (tests) never see a recovery prompt, so they replay the same everywhere.
    dialogs.askRecover = dialogs.offeredRecovery.has_value() && !script;
    int failures = 0;
    auto previous = std::chrono::steady_clock::now();
    while (!dialogs.quitNow) {
        const auto frameStart = std::chrono::steady_clock::now();
        input.beginFrame();
        ScriptActions actions;
        if (script) {
            glfwPollEvents();
            actions = playScriptFrame(*script, frameNumber, input);
        } else if (gpu.refined(view.adaptive) && !ImGui::IsAnyItemActive() && !gesture.active) {
            glfwWaitEventsTimeout(0.25); // idle: wake for input or the file poll
        } else {
            glfwPollEvents();
        }
        input.finishEvents();
        if (window->shouldClose()) {
            window->setShouldClose(false);
            requestClose(dialogs, session.document);
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
        startGesture(); // before the session.camera, so the S of "scale" does not also fly back
        handleCamera(seconds);
        handleViewportMouse();
        updateGesture();
        drawUi();
        if (!ImGui::IsAnyItemActive() && !gesture.active && session.document.hasPendingChange())
            session.document.commit();
        if (!editor::selectionValid(session.document.scene(), session.document.selection))
            session.document.selection = editor::Selection::none();
        pollFiles();
        gpu.updateScene(session.document.scene(), session.document.revision(), messages.sceneError);
        gpu.chooseSdfMap(session.document.scene(), session.document.selection, actions.waitShaders,
                         frameNumber, messages.sceneError);
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
        if (actions.quit) requestClose(dialogs, session.document);
        window->swapBuffers();
        frameMilliseconds =
            std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - frameStart)
                .count();
        ++frameNumber;
        if (script && !dialogs.quitNow && frameNumber > script->lastFrame() + 30) {
            std::fprintf(stderr, "rmsc view: the script ended without the viewer quitting%s\n",
                         session.document.dirty() ? " (unsaved changes)" : "");
            return kExitSystem;
        }
    }
    if (!session.document.dirty())
        editor::removeRecovery(session.document.file()); // closed cleanly
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
