// The view's render thread (see view_render_thread.hpp): requests in, pictures out.
#include "view_render_thread.hpp"

#include "editor_file_source.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

namespace rmsc::app {

namespace {

// While it refines, the thread wakes the UI for a band at most this often, and lets the frame it
// woke finish before it starts the next band (at most kYield later): on a machine with few
// cores a UI frame and a band slow each other down, and a frame per band made the refinement a
// third slower (docs/performance.md, "UI frame time").
constexpr std::chrono::milliseconds kBandWake{100};
constexpr std::chrono::milliseconds kYield{40};

// The share of the UI's frame time one render of the thread (a reduced render, a band) is sized
// for. Drivers run the draws of all contexts in turn (llvmpipe in one queue), so a UI frame whose
// draw comes behind a render waits for it: sized for the whole frame time, renders of the
// 4,096-sphere tree put 0 to 2 UI frames a run over the target (33.1 and 35.0 ms), for 60% of it
// none; the refinement after a camera change took 9% longer there, 4% on the grid
// (docs/performance.md, "UI frame time").
constexpr float kRenderShare = 0.6f;

// Asks for the same picture as `b` (its render settings and lights go with the revision; the
// frame number only names it in the log).
bool sameView(const ViewFrameRequest& a, const ViewFrameRequest& b) {
    return a.view.camera == b.view.camera && a.view.revision == b.view.revision &&
           a.view.selected == b.view.selected && a.view.selectedLight == b.view.selectedLight &&
           a.view.showLights == b.view.showLights && a.view.mode == b.view.mode &&
           a.live == b.live && a.width == b.width && a.height == b.height &&
           a.adaptive.enabled == b.adaptive.enabled &&
           a.adaptive.targetMilliseconds == b.adaptive.targetMilliseconds;
}

} // namespace

std::mutex& glSubmissionMutex() {
    static std::mutex mutex;
    return mutex;
}

ViewRenderThread::ViewRenderThread(Window& window) : preparing_(editorFileSource()) {
    threadWindow_ = Window::openHidden(startError_, &window);
    window.makeCurrent(); // (creating a window may leave another context current)
    std::string warmerError;
    warmerWindow_ = Window::openHidden(warmerError);
    window.makeCurrent();
    if (!warmerWindow_)
        std::fprintf(stderr, "rmsc view: shaders are not built in the background (%s)\n",
                     warmerError.c_str());
    view_ = std::make_unique<ViewRenderer>(warmerWindow_.get());
    if (threadWindow_) thread_ = std::thread([this] { run(); });
    warmCopies();
}

// The driver builds what a copy into the window needs at its first use (llvmpipe: the shaders
// of its blitter, 30 to 40 ms), which would fall in the frame that first shows a picture: it is
// built here, with the window, for both filters update() uses. The texture's sides are not
// powers of two, as a viewport's seldom are: llvmpipe builds other code for those.
void ViewRenderThread::warmCopies() {
    std::lock_guard submitting(glSubmissionMutex());
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGBA8, 3, 3);
    gl::Framebuffer source = gl::createFramebuffer();
    glNamedFramebufferTexture(source.id(), GL_COLOR_ATTACHMENT0, texture.id(), 0);
    glBlitNamedFramebuffer(source.id(), 0, 0, 0, 3, 3, 0, 0, 3, 3, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBlitNamedFramebuffer(source.id(), 0, 0, 0, 3, 3, 0, 0, 2, 2, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glFinish();
}

ViewRenderThread::~ViewRenderThread() {
    if (thread_.joinable()) {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        changed_.notify_all();
        thread_.join();
    }
    for (Slot& slot : slots_)
        if (slot.shown) glDeleteSync(slot.shown);
}

void ViewRenderThread::run() {
    threadWindow_->makeCurrent();
    std::optional<ViewFrameRequest> frame; // the last request: refining goes on with it
    std::optional<ViewFrameRequest> drawn; // the request of the last picture
    std::chrono::steady_clock::time_point lastWake;
    // Whether a band woke the UI, and the UI's frames done then. (Two plain values: GCC 12 warned
    // that an optional's value might be read uninitialized, which it cannot be.)
    bool wokeUi = false;
    std::uint64_t uiFramesAtWake = 0;
    for (;;) {
        std::uint64_t serial = 0;
        Job job = Job::None;
        bool poll = false; // nothing asked: only see whether a worker's result changes the view
        {
            std::unique_lock lock(mutex_);
            auto asked = [this] {
                return stopping_ || (job_ != Job::None && !jobTaken_) || pending_.has_value() ||
                       refining_;
            };
            // While a worker's result is awaited (a map being built, the newest scene's cells),
            // it is looked for every few milliseconds, as the UI's frames once did.
            if (frame && view_->waitsForBackground())
                poll = !changed_.wait_for(lock, std::chrono::milliseconds(15), asked);
            else
                changed_.wait(lock, asked);
            if (stopping_) break;
            // The next band waits for the UI frame the last one woke (nothing else does).
            if (wokeUi && !pending_ && (job_ == Job::None || jobTaken_) && refining_) {
                const std::uint64_t woke = uiFramesAtWake;
                changed_.wait_for(lock, kYield, [this, woke] {
                    return stopping_ || pending_.has_value() || (job_ != Job::None && !jobTaken_) ||
                           uiFramesDone_ > woke;
                });
                if (stopping_) break;
            }
            wokeUi = false;
            // A frame the UI posted before it asked for a job first: a capture shows the scene
            // that frame asked for.
            if (pending_) {
                frame = std::move(pending_);
                pending_.reset();
                serial = posted_;
            } else if (job_ != Job::None && !jobTaken_) {
                job = job_;
                jobTaken_ = true;
            } else {
                serial = done_; // the next band of the last request
            }
        }
        if (job != Job::None) {
            runJob(job);
        } else {
            const bool news = !drawn || !sameView(*drawn, *frame);
            const bool rendered = step(*frame, serial, poll);
            // A UI waiting for input shows the new picture.
            const auto now = std::chrono::steady_clock::now();
            const bool band = rendered && !news && view_->refining();
            if (news || (rendered && !band) || (band && now - lastWake >= kBandWake)) {
                if (band) {
                    std::lock_guard lock(mutex_);
                    wokeUi = true;
                    uiFramesAtWake = uiFramesDone_;
                }
                glfwPostEmptyEvent();
                lastWake = now;
            }
            drawn = frame;
        }
    }
    // GL objects go while their context is current: the renderer's, the slots' textures and
    // this context's framebuffers.
    view_.reset();
    for (Slot& slot : slots_) {
        slot.drawFbo = {};
        slot.color = {};
    }
    Window::releaseCurrent();
}

void ViewRenderThread::runJob(Job job) {
    std::unique_lock submitting(glSubmissionMutex());
    bool ok = false;
    std::string error;
    std::optional<Pixels<std::uint8_t>> image;
    if (job == Job::Shaders) {
        ShaderFiles files;
        {
            std::lock_guard lock(mutex_);
            files = std::move(shaderFiles_);
        }
        ok = view_->useShaders(std::move(files), error);
    } else {
        ViewInput view;
        int width = 0, height = 0;
        {
            std::lock_guard lock(mutex_);
            view = captureView_;
            width = captureWidth_;
            height = captureHeight_;
        }
        image = view_->capture(view, width, height, error);
        ok = image.has_value();
    }
    submitting.unlock();
    {
        std::lock_guard lock(mutex_);
        jobOk_ = ok;
        jobError_ = std::move(error);
        captured_ = std::move(image);
        hasShaders_ = view_->hasShaders();
        jobDone_ = true;
    }
    changed_.notify_all();
}

int ViewRenderThread::drawSlot(int width, int height, std::unique_lock<std::mutex>& submitting) {
    int chosen = 0;
    GLsync shown = nullptr;
    {
        std::lock_guard lock(mutex_);
        for (int i = 0; i < int(slots_.size()); ++i)
            if (i != shownSlot_ && !slots_[std::size_t(i)].reading) {
                chosen = i;
                break;
            }
        shown = std::exchange(slots_[std::size_t(chosen)].shown, nullptr);
    }
    // The UI's copy from it (made before the fence, flushed after it) must be done before this
    // thread draws over it.
    if (shown) {
        submitting.unlock(); // (the UI flushed its fence)
        glClientWaitSync(shown, 0, 1'000'000'000);
        submitting.lock();
        glDeleteSync(shown);
    }
    Slot& slot = slots_[std::size_t(chosen)];
    if (slot.width != width || slot.height != height || !slot.color) {
        slot.color = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(slot.color.id(), 1, GL_RGBA8, width, height);
        slot.drawFbo = gl::createFramebuffer();
        glNamedFramebufferTexture(slot.drawFbo.id(), GL_COLOR_ATTACHMENT0, slot.color.id(), 0);
        slot.width = width;
        slot.height = height;
        ++slot.generation;
    }
    return chosen;
}

bool ViewRenderThread::step(const ViewFrameRequest& request, std::uint64_t serial, bool poll) {
    std::optional<CompiledScene> compiled;
    {
        std::lock_guard lock(mutex_);
        compiled = std::exchange(compiled_, std::nullopt);
    }
    std::unique_lock submitting(glSubmissionMutex());
    if (compiled) view_->takeScene(*compiled);
    std::optional<std::string> sceneError;
    int frameNumber = request.frameNumber;
    {
        std::lock_guard lock(mutex_);
        frameNumber = uiFrame_; // the log names the UI frame this happens in
    }
    view_->chooseSdfMap(request.live, request.waitForBuilds, frameNumber, sceneError);
    if (poll && !view_->wouldRender(request.view, request.width, request.height)) {
        // Nothing new to draw: the picture shown stays, and what the map choice said stays.
        if (sceneError) publishSceneError(std::move(*sceneError));
        return false;
    }
    adaptive_.enabled = request.adaptive.enabled;
    adaptive_.targetMilliseconds = request.adaptive.targetMilliseconds;
    const int slot = drawSlot(request.width, request.height, submitting);
    const bool rendered = view_->render(
        request.view, slots_[std::size_t(slot)].drawFbo.id(), request.width, request.height,
        adaptive_, kRenderShare * adaptive_.targetMilliseconds, request.refineAll);
    if (rendered && view_->lastRenderCompileMs() > 0.0)
        std::fprintf(stderr,
                     "rmsc view: frame %d: built the shaders of the view's shading settings in "
                     "%.0f ms (on the render thread)\n",
                     frameNumber, view_->lastRenderCompileMs());
    // The picture is whole before the UI copies it (waited for outside the lock).
    GLsync whole = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();
    submitting.unlock();
    glClientWaitSync(whole, 0, GL_TIMEOUT_IGNORED);
    submitting.lock();
    glDeleteSync(whole);
    submitting.unlock();
    {
        std::lock_guard lock(mutex_);
        shownSlot_ = slot;
        done_ = serial;
        status_ = view_->status();
        refined_ = view_->refined();
        refining_ = view_->refining();
        drawnPublished_ = view_->drawnScene();
    }
    if (sceneError) publishSceneError(std::move(*sceneError));
    changed_.notify_all();
    return rendered;
}

void ViewRenderThread::publishSceneError(std::string message) {
    std::lock_guard lock(mutex_);
    sceneError_ = std::move(message);
    ++sceneErrorStamp_;
}

void ViewRenderThread::waitForJob(Job job) {
    std::unique_lock lock(mutex_);
    job_ = job;
    jobTaken_ = false;
    jobDone_ = false;
    changed_.notify_all();
    changed_.wait(lock, [this] { return jobDone_; });
    job_ = Job::None;
}

bool ViewRenderThread::useShaders(ShaderFiles files, std::string& error) {
    if (!thread_.joinable()) {
        error = "the view has no render thread: " + startError_;
        return false;
    }
    {
        std::lock_guard lock(mutex_);
        shaderFiles_ = std::move(files);
    }
    waitForJob(Job::Shaders);
    std::lock_guard lock(mutex_);
    error = jobError_;
    return jobOk_;
}

bool ViewRenderThread::hasShaders() const {
    std::lock_guard lock(mutex_);
    return hasShaders_;
}

std::optional<Pixels<std::uint8_t>> ViewRenderThread::capture(const ViewInput& view, int width,
                                                              int height, std::string& error) {
    if (!thread_.joinable()) {
        error = "nothing is rendered";
        return std::nullopt;
    }
    {
        std::lock_guard lock(mutex_);
        captureView_ = view;
        captureWidth_ = width;
        captureHeight_ = height;
    }
    waitForJob(Job::Capture);
    std::lock_guard lock(mutex_);
    error = jobError_;
    return std::move(captured_);
}

bool ViewRenderThread::update(const Scene& scene, const ViewFrameRequest& request,
                              const ViewportPixels& viewport, std::string& sceneError) {
    bool wait = request.waitForBuilds;
    if (request.view.revision != requestedRevision_) {
        requestedRevision_ = request.view.revision;
        preparing_.request(requestedRevision_, scene);
        const bool small =
            newest_ && effectiveSdfStrategy(newest_->sdf, SdfStrategy::Baked) != SdfStrategy::Cells;
        wait = wait || small;
    }
    if (wait) preparing_.waitUntilIdle();
    std::optional<editor::ScenePreparingResult> result = preparing_.take();
    // (An older revision's is dropped: the newest is compiled next.)
    std::optional<CompiledScene> compiled;
    if (result && result->revision == requestedRevision_) {
        compiled.emplace();
        compiled->revision = result->revision;
        if (result->prepared) {
            compiled->prepared =
                std::make_shared<const PreparedScene>(std::move(*result->prepared));
            compiled->bounded = std::make_shared<const SdfProgram>(std::move(result->bounded));
            compiled->warning = std::move(result->warning);
            newest_ = compiled->prepared;
        } else {
            sceneError =
                "The scene does not compile (showing the last one that did):\n" + result->error;
        }
    }
    int slot = -1;
    std::uint64_t generation = 0;
    GLuint texture = 0;
    int width = 0, height = 0;
    if (thread_.joinable()) {
        std::unique_lock lock(mutex_);
        uiFrame_ = request.frameNumber;
        const bool waits = request.waitForBuilds || request.refineAll || request.waitForView;
        // Posted when it asks for something else or brings a compiled scene (the thread looks
        // for its workers' results on its own).
        if (waits || compiled || !lastPosted_ || !sameView(*lastPosted_, request)) {
            if (compiled) compiled_ = std::move(compiled);
            pending_ = request;
            lastPosted_ = request;
            const std::uint64_t serial = ++posted_;
            changed_.notify_all();
            if (waits) changed_.wait(lock, [this, serial] { return done_ >= serial; });
        }
        drawn_ = drawnPublished_;
        if (sceneErrorStamp_ != sceneErrorSeen_) {
            sceneErrorSeen_ = sceneErrorStamp_;
            sceneError = sceneError_;
        }
        slot = shownSlot_;
        if (slot >= 0) {
            Slot& shown = slots_[std::size_t(slot)];
            shown.reading = true;
            generation = shown.generation;
            texture = shown.color.id();
            width = shown.width;
            height = shown.height;
        }
    }
    std::lock_guard submitting(glSubmissionMutex());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, viewport.framebufferWidth, viewport.framebufferHeight);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (slot < 0) return wait;
    Slot& shown = slots_[std::size_t(slot)];
    if (!shown.readFbo) shown.readFbo = gl::createFramebuffer();
    if (shown.readGeneration != generation) {
        glNamedFramebufferTexture(shown.readFbo.id(), GL_COLOR_ATTACHMENT0, texture, 0);
        shown.readGeneration = generation;
    }
    // Stretched while the viewport's size changes (the thread then draws the new size).
    const bool sameSize = width == viewport.width && height == viewport.height;
    glBlitNamedFramebuffer(shown.readFbo.id(), 0, 0, 0, width, height, viewport.x, viewport.y,
                           viewport.x + viewport.width, viewport.y + viewport.height,
                           GL_COLOR_BUFFER_BIT, sameSize ? GL_NEAREST : GL_LINEAR);
    GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush(); // so the thread's wait on the fence ends
    std::lock_guard lock(mutex_);
    if (shown.shown) glDeleteSync(shown.shown);
    shown.shown = fence;
    shown.reading = false;
    return wait;
}

void ViewRenderThread::frameDone() {
    {
        std::lock_guard lock(mutex_);
        ++uiFramesDone_;
    }
    changed_.notify_all();
}

bool ViewRenderThread::refined() const {
    std::lock_guard lock(mutex_);
    return refined_ && !pending_ && done_ == posted_;
}

bool ViewRenderThread::pictureComing() const {
    std::lock_guard lock(mutex_);
    return refining_ || pending_ || done_ != posted_;
}

ViewStatus ViewRenderThread::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

} // namespace rmsc::app
