// `rmsc view`: the frame loop, the GPU copy of the scene, rendering with adaptive resolution,
// picking by CPU ray casts, screenshots and the scene / shader files (see viewer_app.hpp).
#include "viewer_app.hpp"
#include "editor/recovery.hpp"

#include "core/exit_code.hpp"
#include "core/image_io.hpp"
#include "editor/editing_map.hpp"
#include "editor/picking.hpp"
#include "editor/scene_edits.hpp"
#include "render/frame.hpp"
#include "render/readback.hpp"
#include "render/shader_library.hpp"
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>

namespace rmsc::app {
namespace {

// Scene files and the glTF files they name: read from disk (each file once per session, so an
// edit does not re-read every mesh), falling back to the embedded samples (the demo).
FileSource editorFileSource() {
    auto cache = std::make_shared<std::map<std::filesystem::path, std::string>>();
    auto disk = std::make_shared<FileSource>(diskFileSource());
    auto embedded = std::make_shared<FileSource>(embeddedFileSource());
    FileSource source;
    source.read = [cache, disk, embedded](const std::filesystem::path& path,
                                          std::string& error) -> std::optional<std::string> {
        if (auto it = cache->find(path); it != cache->end()) return it->second;
        std::optional<std::string> bytes = disk->read(path, error);
        if (!bytes) {
            std::string embeddedError;
            bytes = embedded->read(path, embeddedError);
            if (!bytes) return std::nullopt;
            error.clear();
        }
        cache->emplace(path, *bytes);
        return bytes;
    };
    return source;
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.up == b.up &&
           a.fovYDegrees == b.fovYDegrees && a.nearPlane == b.nearPlane && a.farPlane == b.farPlane;
}

} // namespace

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
    lastRenderedCamera.fovYDegrees = -1.0f;
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
    std::optional<Renderer> newRenderer = Renderer::create(files, error);
    // The scene's SDF passes too, so a broken shader is found here and not while drawing.
    if (newRenderer && gpuScene && !newRenderer->prepare(*gpuScene, error)) newRenderer.reset();
    std::optional<DisplayPass> newDisplay;
    if (newRenderer) newDisplay = DisplayPass::create(files, error);
    if (newRenderer && newDisplay) {
        renderer = std::move(newRenderer);
        renderer->setGroundGrid(true);
        display = std::move(newDisplay);
        shaderFiles = std::move(files);
        startWarmer();
        if (!initial) notice("shaders reloaded");
        shaderError.clear();
        lastRenderedRevision = 0; // render again
        return true;
    }
    shaderError = "Shader error (the previous shaders stay in use):\n" + error;
    std::fprintf(stderr, "rmsc view: %s\n", shaderError.c_str());
    if (initial && !files.overrideDirectory.empty()) {
        // The shaders on disk are broken: start with the embedded ones.
        files = embeddedShaderFiles();
        newRenderer = Renderer::create(files, error);
        if (newRenderer) newDisplay = DisplayPass::create(files, error);
        if (newRenderer && newDisplay) {
            renderer = std::move(newRenderer);
            renderer->setGroundGrid(true);
            display = std::move(newDisplay);
            shaderFiles = std::move(files);
            startWarmer();
            return true;
        }
    }
    return renderer.has_value();
}

void Viewer::syncGpuScene() {
    if (document.revision() == uploadedRevision) return;
    uploadedRevision = document.revision();
    static const FileSource files = editorFileSource();
    Diagnostics diagnostics;
    // Without the bounding hierarchy: its order follows where things are, and a drag must
    // never change the program's structure (the maps for editing would need another build).
    std::optional<PreparedScene> next =
        prepareScene(document.scene(), files, diagnostics, ShellMode::AsScene, false);
    if (!next) {
        sceneError =
            "The scene does not compile (showing the last one that did):\n" + diagnostics.format();
        return;
    }
    // The interpreter's program: with the hierarchy, the interpreter skips parts by their boxes,
    // and its text stays the same whatever the order.
    boundedSdf = {};
    if (document.scene().sdf && !next->sdf.instructions.empty())
        if (std::optional<CompiledSdfScene> compiled = compileSdfScene(
                *document.scene().sdf, std::uint32_t(document.scene().materials.size()),
                document.scene().file.string(), diagnostics, {.bounds = true}))
            boundedSdf = std::move(compiled->main);
    if (boundedSdf.instructions.empty()) boundedSdf = next->sdf;
    // Drawn as soon as chooseSdfMap finds a map for it ready, which after a structural edit may
    // take a background build: the picture on screen stays until then.
    prepared = std::move(next);
    sceneChanged = true;
}

void Viewer::startWarmer() {
    warmer.reset();     // waits for the build it is doing
    choiceRevision = 0; // choose the map again
    std::string error;
    if (!warmerWindow) warmerWindow = Window::openHidden(error);
    if (!warmerWindow) {
        std::fprintf(stderr, "rmsc view: shaders are not built in the background (%s)\n",
                     error.c_str());
        return;
    }
    Window* context = warmerWindow.get();
    warmer = std::make_unique<ShaderWarmer>(
        [context](std::string&) -> std::function<void()> {
            context->makeCurrent();
            return [] { Window::releaseCurrent(); };
        },
        shaderFiles);
}

void Viewer::chooseSdfMap(bool waitForBuilds) {
    if (!renderer || !prepared) return;
    if (warmer) {
        if (waitForBuilds) warmer->waitUntilIdle();
        const std::string error = warmer->takeError();
        if (!error.empty()) std::fprintf(stderr, "rmsc view: %s\n", error.c_str());
    }
    const SdfLiveRange live = editor::selectionLiveRange(document.scene(), document.selection);
    const std::size_t built = warmer ? warmer->finishedCount() : 0;
    if (choiceRevision == uploadedRevision && choiceLive.first == live.first &&
        choiceLive.last == live.last && choiceBuilt == built)
        return;
    choiceRevision = uploadedRevision;
    choiceLive = live;
    choiceBuilt = built;
    // Without a warmer, or for the first picture, every map is built here when it is drawn.
    const bool first = !gpuScene;
    if (first) choiceRevision = 0; // choose again next frame: the other maps build meanwhile
    auto isReady = [this, first](const std::string& map) {
        return !warmer || first || renderer->hasPrograms(map) || warmer->isWarm(map);
    };
    editor::EditingMaps maps = editor::chooseEditingMaps(prepared->sdf, boundedSdf, live, isReady);
    if (warmer) {
        warmer->request(*prepared, maps.build);
        if (waitForBuilds && !maps.build.empty()) {
            warmer->waitUntilIdle();
            maps = editor::chooseEditingMaps(prepared->sdf, boundedSdf, live, isReady);
            choiceBuilt = warmer->finishedCount();
        }
    }
    if (maps.draw.empty() || (!sceneChanged && !gpuScene))
        return; // nothing ready for the newest scene: the old picture stays
    const bool sameMap = gpuScene && gpuScene->sdfMap == maps.draw;
    const bool bounded = maps.kind == editor::EditingMapKind::Interpreter;
    if (sameMap && !sceneChanged) return;
    std::optional<GpuScene> fresh; // a new upload: a newer scene, or the other program
    if (sceneChanged || bounded != drawnBounded) {
        if (bounded) std::swap(prepared->sdf, boundedSdf);
        fresh = uploadScene(*prepared, SdfStrategy::Buffer);
        if (bounded) std::swap(prepared->sdf, boundedSdf);
    }
    GpuScene& next = fresh ? *fresh : *gpuScene;
    std::string previous = std::exchange(next.sdfMap, maps.draw);
    std::string error;
    if (!renderer->prepare(next, error)) { // not expected: maps are generated
        next.sdfMap = std::move(previous);
        sceneChanged = false;
        sceneError =
            "The scene's shaders do not build (showing the last scene that did):\n" + error;
        std::fprintf(stderr, "rmsc view: %s\n", sceneError.c_str());
        return;
    }
    const double compileMs = renderer->lastCompileMs();
    if (fresh) {
        gpuScene = std::move(*fresh);
        drawnBounded = bounded;
        if (sceneChanged) sceneError.clear();
        sceneChanged = false;
        lastRenderedRevision = 0; // the picture may show an older scene: render again
    }
    if (sameMap) return;
    const std::string name(editor::editingMapName(maps.kind));
    const bool background = warmer && warmer->isWarm(maps.draw);
    if (!background && compileMs > 0.0)
        std::fprintf(stderr, "rmsc view: frame %d: built the %s map's shaders in %.0f ms\n",
                     frameNumber, name.c_str(), compileMs);
    std::fprintf(stderr, "rmsc view: frame %d: drawing with the %s map (%s)\n", frameNumber,
                 name.c_str(),
                 background ? ("built in the background in " +
                               std::to_string(int(warmer->buildMs(maps.draw))) + " ms, " +
                               std::to_string(int(compileMs)) + " ms to switch")
                                  .c_str()
                 : compileMs > 0 ? "built here"
                                 : "built before");
    drawnMap = maps.kind;
}

void Viewer::renderView() {
    int ww = 0, wh = 0, fw = 0, fh = 0;
    window->windowSize(ww, wh);
    window->framebufferSize(fw, fh);
    const float sx = ww > 0 ? float(fw) / float(ww) : 1.0f;
    const float sy = wh > 0 ? float(fh) / float(wh) : 1.0f;
    const int vx = int(viewport.x * sx), vw = std::max(1, int(viewport.width * sx));
    const int vh = std::max(1, int(viewport.height * sy));
    const int vy = fh - int((viewport.y + viewport.height) * sy);

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!renderer || !display || !gpuScene) return;

    const Camera view = viewCamera();
    const bool sizeChanged =
        !targets || (lastRenderScale >= 1.0f &&
                     (targets->display.width != vw || targets->display.height != vh));
    viewChanged = !sameCamera(view, lastRenderedCamera) ||
                  lastRenderedRevision != document.revision() || sizeChanged;
    const float scale = adaptive.next(viewChanged, lastRenderMilliseconds, lastRenderScale);
    const int tw = std::max(1, int(std::lround(float(vw) * scale)));
    const int th = std::max(1, int(std::lround(float(vh) * scale)));
    const bool needRender = viewChanged || scale != lastRenderScale || !targets ||
                            targets->display.width != tw || targets->display.height != th;
    if (needRender) {
        if (!targets || targets->display.width != tw || targets->display.height != th)
            targets = createFrameTargets(tw, th);
        const auto t0 = std::chrono::steady_clock::now();
        renderer->render(*gpuScene, view, document.scene().render, *targets);
        glFinish();
        lastRenderMilliseconds =
            float(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                      .count());
        lastRenderScale = scale;
        lastRenderedCamera = view;
        lastRenderedRevision = document.revision();
    }
    const editor::IdRange ids = editor::objectIdRange(document.scene(), document.selection);
    DisplayInput in;
    in.frame = &*targets;
    in.mode = viewMode;
    in.selectedFirst = ids.first;
    in.selectedLast = ids.last;
    in.nearPlane = view.nearPlane;
    in.farPlane = std::min(view.farPlane, document.scene().render.maxDistance);
    in.maxSteps = document.scene().render.maxSteps;
    in.x = vx;
    in.y = vy;
    in.width = vw;
    in.height = vh;
    display->draw(in);
}

void Viewer::pick(glm::vec2 p) {
    if (!prepared || !viewport.contains(p)) return;
    // A ray from the eye through the clicked point, built as the march pass builds its rays
    // (pixelRayDirection adds half a pixel, so the point itself is the pixel's centre).
    const Camera view = viewCamera();
    const int w = std::max(1, int(viewport.width)), h = std::max(1, int(viewport.height));
    const FrameCamera frame = makeFrameCamera(view, w, h);
    const float x = p.x - viewport.x - 0.5f;
    const float y = viewport.height - (p.y - viewport.y) - 0.5f; // rows counted from the bottom
    const glm::vec3 direction = pixelRayDirection(frame, x, y, w, h); // forward component 1
    const float length = glm::length(direction);
    editor::PickRay ray;
    ray.origin = view.position;
    ray.direction = direction / length;
    ray.tMin = view.nearPlane * length; // the near and far planes are view depths
    ray.tMax = view.farPlane * length;
    const std::optional<editor::PickHit> hit = editor::pick(*prepared, ray);
    document.selection = hit ? editor::selectionForObjectId(document.scene(), hit->objectId)
                             : editor::Selection::none();
}

bool Viewer::writeScreenshot(const std::string& path, std::string& error) {
    if (!renderer || !gpuScene) {
        error = "nothing is rendered";
        return false;
    }
    int ww = 0, wh = 0, fw = 0, fh = 0;
    window->windowSize(ww, wh);
    window->framebufferSize(fw, fh);
    const int w = std::max(1, int(viewport.width * float(fw) / float(std::max(ww, 1))));
    const int h = std::max(1, int(viewport.height * float(fh) / float(std::max(wh, 1))));
    if (targets && targets->display.width == w && targets->display.height == h &&
        lastRenderScale >= 1.0f && sameCamera(viewCamera(), lastRenderedCamera) &&
        lastRenderedRevision == document.revision())
        return writePng8(path, readDisplayColor(*targets), error); // the view is already refined
    FrameTargets shot = createFrameTargets(w, h);
    renderer->render(*gpuScene, viewCamera(), document.scene().render, shot);
    return writePng8(path, readDisplayColor(shot), error);
}

bool Viewer::writeWindowShot(const std::string& path, std::string& error) {
    int fw = 0, fh = 0;
    window->framebufferSize(fw, fh);
    Pixels<std::uint8_t> image;
    image.width = fw;
    image.height = fh;
    image.channels = 4;
    image.data.resize(std::size_t(fw) * std::size_t(fh) * 4);
    std::vector<std::uint8_t> rows(image.data.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    for (int y = 0; y < fh; ++y) // GL reads bottom row first; images store the top row first
        std::copy_n(rows.data() + std::size_t(fh - 1 - y) * std::size_t(fw) * 4,
                    std::size_t(fw) * 4, image.data.data() + std::size_t(y) * std::size_t(fw) * 4);
    return writePng8(path, image, error);
}

void Viewer::screenshotToDefaultFile() {
    char stamp[32];
    const std::time_t t = std::time(nullptr);
    std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", std::localtime(&t));
    const std::filesystem::path folder =
        document.file().empty() ? std::filesystem::current_path() : document.file().parent_path();
    const std::filesystem::path path = folder / ("rmsc-screenshot-" + std::string(stamp) + ".png");
    std::string error;
    if (writeScreenshot(path.string(), error))
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
        } else if (!viewChanged && adaptive.refined(lastRenderScale) && !ImGui::IsAnyItemActive() &&
                   !gesture.active) {
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
        const float top = ImGui::GetFrameHeight();
        // Panels take at most about half of a small window.
        leftPanelWidth = std::clamp(float(ww) * 0.24f, 150.0f, 270.0f);
        rightPanelWidth = std::clamp(float(ww) * 0.28f, 200.0f, 340.0f);
        viewport = {leftPanelWidth, top,
                    std::max(1.0f, float(ww) - leftPanelWidth - rightPanelWidth),
                    std::max(1.0f, float(wh) - top)};

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
        syncGpuScene();
        chooseSdfMap(actions.waitShaders);
        renderView();

        ImGui::Render();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        for (const std::string& path : actions.screenshots) {
            std::string error;
            if (!writeScreenshot(path, error)) {
                std::fprintf(stderr, "rmsc view: screenshot %s: %s\n", path.c_str(), error.c_str());
                ++failures;
            }
        }
        for (const std::string& path : actions.windowShots) {
            std::string error;
            if (!writeWindowShot(path, error)) {
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
