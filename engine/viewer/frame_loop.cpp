// The viewer's frame loop and what it ties together (see frame_loop.hpp).
#include "frame_loop.hpp"

#include "core/exit_code.hpp"
#include "editor/dropped_files.hpp"
#include "editor/gltf_contents.hpp"
#include "editor/multi_selection.hpp"
#include "editor/recent_files.hpp"
#include "editor/recovery.hpp"
#include "editor/scene_edits.hpp"
#include "hierarchy_panel.hpp"
#include "imgui_platform.hpp"
#include "menu_bar.hpp"
#include "overlay.hpp"
#include "render/shader_library.hpp"
#include "screenshots.hpp"
#include "shortcut_sheet.hpp"
#include "shortcuts.hpp"
#include "view_shortcuts.hpp"
#include "viewport_pick.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace rmsc::app {

Viewer::Viewer(const ViewerOptions& options, std::unique_ptr<Window> window,
               std::optional<Script> script)
    : options_(options), window_(std::move(window)), script_(std::move(script)),
      start_(std::chrono::steady_clock::now()), gpu_(*window_) {
    view_.adaptive.targetMilliseconds = options_.targetMilliseconds;
    files_.recentFile = editor::recentFilesPath();
    loadRecentFiles(files_, messages_);
    openStartScene(options_.scene, session_, files_, messages_);
    dialogs_.offeredRecovery = editor::findRecovery(session_.document.file());
}

Viewer::~Viewer() = default;

double Viewer::now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

int Viewer::run() {
    if (!loadShaders(true)) {
        std::fprintf(stderr, "rmsc view: %s\n", messages_.shaderError.c_str());
        return kExitSystem;
    }
    // A replayed run still takes files dropped on its window (a test can drop them for real).
    attachGlfwInput(window_->handle(), &queue_, script_.has_value());
    // Scripted runs (tests) never see a recovery prompt, so they replay the same everywhere.
    dialogs_.askRecover = dialogs_.offeredRecovery.has_value() && !script_;
    int failures = 0;
    auto previous = std::chrono::steady_clock::now();
    while (!dialogs_.quitNow) {
        const ScriptActions actions = readInput(); // may wait for input when idle
        const auto frameStart = std::chrono::steady_clock::now();
        const auto nowTime = std::chrono::steady_clock::now();
        const float seconds =
            script_ ? 1.0f / 30.0f
                    : std::min(0.1f, std::chrono::duration<float>(nowTime - previous).count());
        previous = nowTime;

        int ww = 0, wh = 0, fw = 0, fh = 0;
        window_->windowSize(ww, wh);
        window_->framebufferSize(fw, fh);
        feedImGui(input_, ww, wh, fw, fh, seconds);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        // The panels follow the font's size: 13 pixels at a UI scale of 1.
        layout_ = layoutPanels(ww, wh, ImGui::GetFrameHeight(), ImGui::GetFontSize() / 13.0f);

        handleInput(seconds);
        playAnimation(seconds);
        drawUi();
        commitFinishedEdits();
        pollFiles();
        updateView(actions.waitShaders, actions.waitView, !actions.windowShots.empty());

        ImGui::Render();
        {
            std::lock_guard submitting(glSubmissionMutex());
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fw, fh);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }

        failures += writeScriptShots(actions);
        if (actions.quit) requestClose(dialogs_, session_, files_, messages_);
        // The window opens hidden and is shown with its first frame: that frame's one-time work
        // (Dear ImGui's font and program, the driver's first draw and first present into the
        // window: 50 to 90 ms on llvmpipe) is done before anyone can see it or give it input.
        // It is the window's opening, not a UI frame.
        const bool opening = !window_->shown();
        if (opening) window_->show();
        {
            std::lock_guard submitting(glSubmissionMutex());
            window_->swapBuffers();
        }
        gpu_.frameDone();
        frameMilliseconds_ =
            std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - frameStart)
                .count();
        if (opening)
            stats_.openingMilliseconds = frameMilliseconds_;
        else if (const std::optional<std::string> line =
                     recordFrame(stats_, gpu_.status(), frameNumber_, frameMilliseconds_,
                                 view_.adaptive.targetMilliseconds, glfwGetTime(), lastInput_);
                 line && options_.stats)
            std::fprintf(stderr, "rmsc view: %s\n", line->c_str());
        ++frameNumber_;
        if (script_ && !dialogs_.quitNow && queue_.empty() &&
            scriptFrame_ > script_->lastFrame() + 30) {
            std::fprintf(stderr, "rmsc view: the script ended without the viewer quitting%s\n",
                         session_.document.dirty() ? " (unsaved changes)" : "");
            return kExitSystem;
        }
        // Counted in seconds, not frames: frames that only wait are short, and an export under
        // the sanitizers on a loaded machine outlasted 5,000 of them.
        if (scriptHoldSince_ >= 0.0 && glfwGetTime() - scriptHoldSince_ > kScriptHoldSeconds) {
            std::fprintf(stderr,
                         "rmsc view: the view was not refined (or the export did not end) in "
                         "%.0f s\n",
                         kScriptHoldSeconds);
            return kExitSystem;
        }
    }
    if (options_.stats)
        std::fprintf(stderr, "rmsc view: %s\n",
                     frameSummary(stats_, view_.adaptive.targetMilliseconds).c_str());
    finishSave(session_.document, files_, messages_, true);
    if (!session_.document.dirty())
        removeRecoveryFile(files_, session_.document.file()); // closed cleanly
    return failures ? kExitSystem : kExitOk;
}

ScriptActions Viewer::readInput() {
    input_.beginFrame();
    if (script_) {
        // While it waits for the refined view, as a person's frames do (below): the next
        // picture wakes it.
        if (scriptHoldSince_ >= 0.0 && gpu_.pictureComing())
            glfwWaitEventsTimeout(0.25);
        else
            glfwPollEvents();
        // The frame that sees the wait end plays nothing: the render thread's refined picture
        // arrives between frames, and this frame shows it (and logs it) before the next input.
        const bool held = scriptHoldSince_ >= 0.0;
        if (held && (scriptWaitsForExport_ ? !export_.job.running() : gpu_.refined()))
            scriptHoldSince_ = -1.0;
        // A save started in the last frame is taken here, waited for if need be (between two
        // frames: a frame's own work is what it measures), so a replay goes the same whatever
        // the machine's speed.
        finishSave(session_.document, files_, messages_, true);
        if (!held) playScriptFrame(*script_, scriptFrame_++, glfwGetTime(), queue_, scriptMods_);
    } else if (queue_.empty() && !ImGui::IsAnyItemActive() && !gesture_.active &&
               !gizmo_.dragging() && !inspector_.playback.playing &&
               (gpu_.refined() || gpu_.pictureComing())) {
        // Idle, or a picture is coming from the render thread, which wakes the loop when it is
        // there: wake for input, the picture, or the file poll (soon while a save is written,
        // to say it is done).
        glfwWaitEventsTimeout(files_.save.underWay() ? 0.02 : 0.25);
    } else {
        glfwPollEvents();
    }
    std::vector<editor::InputEvent> taken;
    if (scriptHoldSince_ < 0.0) taken = queue_.takeFrame();
    for (const editor::InputEvent& e : taken) {
        input_.apply(e);
        if (e.kind != editor::InputEvent::Kind::Marker) lastInput_ = std::max(lastInput_, e.time);
    }
    ScriptActions actions;
    if (script_) actions = scriptActions(*script_, taken);
    if (actions.waitRefined || actions.waitExport) {
        scriptHoldSince_ = glfwGetTime();
        scriptWaitsForExport_ = actions.waitExport;
    }
    input_.finishEvents();
    if (window_->shouldClose()) {
        window_->setShouldClose(false);
        requestClose(dialogs_, session_, files_, messages_);
    }
    return actions;
}

void Viewer::handleInput(float seconds) {
    ViewerCommands commands;
    handleShortcuts(input_, gesture_, gizmo_.dragging(), commands);
    for (const std::string& path : input_.drops)
        commands.push_back({ViewerCommand::DropFile, path});
    carryOut(commands);
    // Before the camera, so the S of "scale" does not also fly back.
    if (!gizmo_.dragging())
        startGesture(gesture_, input_, session_, layout_.viewport, inspector_.worldCoordinates,
                     gizmo_.steps);
    // Before the click to select: a press on a handle drags it and selects nothing.
    handleGizmo(gizmo_, input_, session_.document, session_.viewCamera(), layout_.viewport,
                inspector_.worldCoordinates, gesture_.active);
    const bool busy = gesture_.active || gizmo_.dragging();
    handleViewShortcuts(input_, busy, session_, messages_);
    // The add menu takes the keys from the frame Shift+A opens it in: its A does not fly.
    handleCamera(input_, layout_.viewport, busy || addSearch_.open || addSearch_.askOpen,
                 cameraDrags_, session_, seconds);
    handleViewportClick(input_, layout_.viewport, busy, gpu_.newestScene(), session_);
    updateGesture(gesture_, input_, session_.document, layout_.viewport);
}

void Viewer::playAnimation(float seconds) {
    inspector_.prepared = gpu_.newestScene();
    editor::AnimationPlayback& playback = inspector_.playback;
    if (!playback.playing) return;
    editor::Document& document = session_.document;
    const int mesh = playback.mesh;
    // While playing, the play is a pending change that nothing commits: when something did (an
    // edit applied, undo, another scene opened), the play has ended. And the mesh playing must
    // still show an animation the compiled scene knows the length of.
    std::optional<editor::GltfContents> contents;
    if (document.hasPendingChange() && mesh >= 0 &&
        std::size_t(mesh) < document.scene().meshes.size() &&
        !document.scene().meshes[std::size_t(mesh)].animation.empty() && inspector_.prepared)
        contents = editor::gltfContents(*inspector_.prepared, mesh);
    if (!contents || contents->animation < 0) {
        editor::pausePlayback(playback);
        return;
    }
    MeshInstance& instance = document.editScene().meshes[std::size_t(mesh)];
    instance.time = editor::advancePlayback(playback, instance.time, seconds,
                                            contents->durations[std::size_t(contents->animation)]);
    document.markChanged("Play animation");
}

void Viewer::drawUi() {
    ViewerCommands commands;
    const NewShapePlace place = newShapePlace();
    if (ImGui::BeginMainMenuBar()) {
        drawMenus(session_, view_, place, export_.job.running(), files_.recent, messages_,
                  commands);
        carryOut(commands); // before the title, which shows whether the scene is saved
        drawMenuBarTitle(session_.document);
        ImGui::EndMainMenuBar();
    }
    drawHierarchyPanel(session_.document, hierarchy_, layout_, place, commands);
    carryOut(commands);
    drawInspectorPanel(session_, inspector_, view_, layout_, commands);
    carryOut(commands);
    if (FileField* field = takeBrowseRequest(inspector_))
        dialogs_.askForFieldFile(*field, session_.document.file().parent_path());
    drawAddSearchMenu(addSearch_, session_.document, place, commands);
    carryOut(commands);
    drawShortcutSheet(shortcutSheet_, layout_.viewport);
    drawStatusOverlay(layout_.viewport, gpu_.status(), frameMilliseconds_, view_,
                      session_.camera.speed, gesture_.active ? &gesture_.math : nullptr, messages_);
    drawGizmo(gizmo_, session_.document, session_.viewCamera(), layout_.viewport,
              inspector_.worldCoordinates);
    const float toolbarWidth = drawViewportToolbar(gizmo_, inspector_.worldCoordinates,
                                                   viewLabel(session_.camera), layout_.viewport);
    drawProblems(layout_.viewport, toolbarWidth, messages_);
    drawDialogs(dialogs_, session_, files_, messages_);
    drawExportDialog(export_, session_.document);
    drawExportProgress(export_, layout_.viewport, messages_);
}

void Viewer::commitFinishedEdits() {
    editor::Document& document = session_.document;
    // Playing an animation is one undo step, from Play to Pause.
    if (!ImGui::IsAnyItemActive() && !gesture_.active && !gizmo_.dragging() &&
        !inspector_.playback.playing && document.hasPendingChange())
        document.commit();
    if (!editor::selectionValid(document.scene(), document.selection))
        document.selection = editor::Selection::none();
}

void Viewer::pollFiles() {
    finishSave(session_.document, files_, messages_, false);
    const double t = now();
    if (t - lastPoll_ < 1.0) return;
    lastPoll_ = t;
    writeRecoveryFile(session_.document, files_, messages_, t);
    if (reloadChangedSceneFile(session_, files_, messages_)) dialogs_.askReload = true;
    if (!shaderWatcher_.path().empty() && shaderWatcher_.changed()) loadShaders(false);
}

void Viewer::updateView(bool waitForBuilds, bool waitForView, bool refineAll) {
    const editor::Document& document = session_.document;
    const auto start = std::chrono::steady_clock::now();
    int ww = 0, wh = 0, fw = 0, fh = 0;
    window_->windowSize(ww, wh);
    window_->framebufferSize(fw, fh);
    const ViewportPixels viewport = viewportPixels(layout_.viewport, ww, wh, fw, fh);
    ViewFrameRequest request;
    request.view = viewInput();
    request.live = editor::selectionLiveRange(document.scene(), document.selection);
    request.width = viewport.width;
    request.height = viewport.height;
    request.adaptive = view_.adaptive;
    request.waitForBuilds = waitForBuilds;
    request.refineAll = refineAll;
    request.waitForView = waitForView;
    request.frameNumber = frameNumber_;
    const bool waitedForCompile =
        gpu_.update(document.scene(), request, viewport, messages_.sceneError);
    if (!waitForBuilds && !waitForView && !refineAll)
        recordSceneWork(
            stats_, frameNumber_,
            std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - start)
                .count(),
            waitedForCompile);
}

int Viewer::writeScriptShots(const ScriptActions& actions) {
    int failures = 0;
    for (const std::string& path : actions.screenshots) {
        std::string error;
        if (!writeViewShot(gpu_, viewInput(), layout_.viewport, *window_, path, error)) {
            std::fprintf(stderr, "rmsc view: screenshot %s: %s\n", path.c_str(), error.c_str());
            ++failures;
        }
    }
    for (const std::string& path : actions.windowShots) {
        std::string error;
        if (!writeWindowShot(*window_, path, error)) {
            std::fprintf(stderr, "rmsc view: window-shot %s: %s\n", path.c_str(), error.c_str());
            ++failures;
        } else {
            std::fprintf(stderr, "rmsc view: frame %d: window shot %s\n", frameNumber_,
                         path.c_str());
        }
    }
    return failures;
}

bool Viewer::loadShaders(bool initial) {
    ShaderFiles shaders = embeddedShaderFiles();
#ifdef RMSC_SOURCE_DIR
    const std::filesystem::path sourceShaders = std::filesystem::path(RMSC_SOURCE_DIR) / "shaders";
    std::error_code ec;
    if (options_.watchShaders && std::filesystem::is_directory(sourceShaders, ec)) {
        shaders.overrideDirectory = sourceShaders.string();
        if (initial) shaderWatcher_ = editor::FileWatcher(sourceShaders);
    }
#endif
    std::string error;
    if (gpu_.useShaders(shaders, error)) {
        if (!initial) messages_.notice("shaders reloaded");
        messages_.shaderError.clear();
        return true;
    }
    messages_.shaderError = "Shader error (the previous shaders stay in use):\n" + error;
    std::fprintf(stderr, "rmsc view: %s\n", messages_.shaderError.c_str());
    // The shaders on disk are broken: start with the embedded ones.
    if (initial && !shaders.overrideDirectory.empty() &&
        gpu_.useShaders(embeddedShaderFiles(), error))
        return true;
    return gpu_.hasShaders();
}

NewShapePlace Viewer::newShapePlace() const {
    NewShapePlace place;
    place.prepared = gpu_.newestScene();
    place.camera = session_.viewCamera();
    // Where the view looks when its centre meets nothing: its focus (the scene camera's target,
    // or what was framed or orbited last), within reason.
    place.fallbackDistance = std::clamp(session_.camera.focusDistance, 0.5f, 50.0f);
    return place;
}

ViewInput Viewer::viewInput() const {
    const editor::Document& document = session_.document;
    ViewInput shown;
    shown.camera = session_.viewCamera();
    shown.render = document.scene().render;
    shown.lights = document.scene().lights;
    shown.revision = document.revision();
    // Outlined by the ids of the scene drawn: after a structural edit whose map is not ready
    // yet, the picture's ids are the old scene's, where the selection's would outline others.
    const PreparedScene* drawn = gpu_.drawnScene();
    if (!drawn || editor::sameObjectIds(drawn->scene, document.scene()))
        for (const editor::Selection& item : editor::selectedItems(document))
            shown.selected.push_back(editor::objectIdRange(document.scene(), item));
    if (document.selection.kind == editor::SelectionKind::Light)
        shown.selectedLight = document.selection.index;
    shown.showLights = view_.showLights;
    shown.mode = view_.mode;
    return shown;
}

glm::vec3 Viewer::viewFocus() const {
    const editor::FlyCamera& camera = session_.camera;
    return camera.position + camera.forward() * camera.focusDistance;
}

void Viewer::dropFile(const std::filesystem::path& path) {
    switch (editor::droppedFileKind(path)) {
    case editor::DroppedKind::Scene:
        requestOpen(dialogs_, path, session_, files_, messages_);
        break;
    case editor::DroppedKind::Mesh: {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) {
            messages_.fileError = path.string() + ": no such file";
            break;
        }
        // Where a new shape goes: on the surface under the view's centre, else at its focus.
        const glm::vec3 where = newShapeSpot(newShapePlace()).point;
        session_.document.apply("Add mesh", [&](Scene& scene, editor::Selection& selection) {
            editor::addMeshAt(scene, selection, path, where);
        });
        messages_.notice("added " + path.filename().string() + " where a new shape goes");
        break;
    }
    case editor::DroppedKind::Unsupported:
        messages_.fileError = editor::droppedFileRefusal(path);
        break;
    }
}

void Viewer::screenshotToDefaultFile() {
    const std::filesystem::path path = defaultScreenshotPath(session_.document.file());
    std::string error;
    if (writeViewShot(gpu_, viewInput(), layout_.viewport, *window_, path.string(), error))
        messages_.notice("screenshot written: " + path.string());
    else
        messages_.fileError = "Screenshot failed: " + error;
}

} // namespace rmsc::app
