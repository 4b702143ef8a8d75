// The view's render thread: the scene is uploaded, its shaders linked and first drawn, and the
// view rendered and composed (view_renderer.hpp) on a thread of its own, on a hidden window's
// context that shares its textures with the UI's. The UI thread only asks for what it wants
// shown and copies the newest finished picture into the viewport, so no UI frame waits for a
// render. (It does wait, at glSubmissionMutex below, while the render thread is in the driver:
// at a program's first draw or a large buffer's creation, tens to hundreds of milliseconds on
// llvmpipe.)
//
// A UI frame posts a request (the camera, the selection, the document's revision) when it asks
// for another picture or brings a newly compiled scene; a newer request replaces one not yet
// taken. The thread takes the newest, does one step of the view with it (a quick render or a
// band of the refinement, as ViewRenderer::render) and publishes the picture, which the next UI
// frame shows. While the picture is not refined it goes on with the last request without waiting
// for another, and while the view waits for a worker (a map being built, cells being pruned) it
// looks for the result on its own; it wakes the UI when it has a new picture (for the bands of a
// refinement at most every 100 ms), so the UI need not draw frames only to move it on
// (pictureComing()). A request that waits (a replay script's wait for the shaders, its view or a
// whole image, a screenshot, new shaders) blocks the UI until its step is done.
//
// The pictures go through three textures: the thread draws into one that is neither shown last
// nor still being read by the UI, and waits for the UI's fence on it before drawing over it.
#pragma once

#include "editor/adaptive_scale.hpp"
#include "editor/scene_preparing_job.hpp"
#include "editor/selection.hpp"
#include "gl/handles.hpp"
#include "panel_layout.hpp"
#include "view_renderer.hpp"
#include "window.hpp"

#include <array>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace rmsc::app {

// Held by the UI thread and the render thread around what they ask of the driver (their GL
// calls but the waits for a fence), so the two contexts, which share objects, never enter it at
// once: llvmpipe (Mesa 22.3) crashed, about one run in ten of the 10,000-shape grid's edits,
// inside a draw of one while the other's upload looked through its queued draws
// (docs/viewer.md, "Responsiveness").
std::mutex& glSubmissionMutex();

// What one UI frame asks of the view.
struct ViewFrameRequest {
    ViewInput view;
    SdfLiveRange live;              // the selection's subtree, kept live in the map chosen
    int width = 1, height = 1;      // of the viewport, in framebuffer pixels
    editor::AdaptiveScale adaptive; // its settings (the thread keeps its own scale)
    bool waitForBuilds = false;     // wait for the maps being built (replay scripts)
    bool refineAll = false;         // render the whole image now (a replay script's window shot)
    bool waitForView = false;       // the UI waits for this request's step (a replay script's)
    int frameNumber = 0;            // the UI's, for the log
};

class ViewRenderThread {
  public:
    // Opens the hidden windows (the thread's, sharing `window`'s objects, and the shader
    // warmer's) and starts the thread. `window` stays current on the calling thread.
    explicit ViewRenderThread(Window& window);
    ~ViewRenderThread(); // finishes the step under way, then ends the thread
    ViewRenderThread(const ViewRenderThread&) = delete;
    ViewRenderThread& operator=(const ViewRenderThread&) = delete;

    // Builds the renderer from `files` on the thread (waits for it); see
    // ViewRenderer::useShaders.
    bool useShaders(ShaderFiles files, std::string& error);
    bool hasShaders() const;

    // Asks for the document's scene compiled when its revision is new (it is copied here,
    // compiled on a worker), and takes the newest compiled one: it waits for the compile unless
    // no scene was compiled yet or the last one is large (drawn with the cells map: its compile
    // takes tens of milliseconds, every frame of a drag), in which case a later frame takes it.
    // Then posts `request` and shows the newest finished picture in `viewport`, after clearing
    // the window. Waits for this request's step when it waits for builds or its view, or refines
    // all.
    // `sceneError` is set when the scene does not compile, and set or cleared as the thread's
    // steps find. Returns whether it waited for the scene's compile.
    bool update(const Scene& scene, const ViewFrameRequest& request, const ViewportPixels& viewport,
                std::string& sceneError);

    // The view at `width` x `height` pixels and full resolution (waits for it).
    std::optional<Pixels<std::uint8_t>> capture(const ViewInput& view, int width, int height,
                                                std::string& error);

    // The newest scene that compiled (what picking casts rays at), or nullptr.
    const PreparedScene* newestScene() const { return newest_.get(); }
    // The scene the picture is drawn from, as last published by the thread (nullptr before the
    // first): its object ids are the id buffer's, which an edit's may not be until its map is
    // ready.
    const PreparedScene* drawnScene() const { return drawn_.get(); }
    // The UI frame is on screen (after its swap): a band waiting for it starts.
    void frameDone();

    // The picture shown is the whole full-resolution image of the newest request: nothing to
    // do until something changes.
    bool refined() const;
    // The thread has a step to do or under way, or refines the picture on its own: a new
    // picture comes and wakes the UI (glfwPostEmptyEvent), which may wait for it or for input.
    bool pictureComing() const;
    ViewStatus status() const;

  private:
    // A picture the thread draws and the UI copies into the window. The texture is shared; each
    // context has its own framebuffer over it.
    struct Slot {
        gl::Texture color;                // made and resized by the thread
        int width = 0, height = 0;        // of `color`
        GLsync shown = nullptr;           // the UI's fence after its last copy from it
        bool reading = false;             // the UI is copying from it (between choosing it and its
                                          // fence)
        gl::Framebuffer drawFbo;          // the thread's
        std::uint64_t generation = 0;     // of `color`: a new texture may reuse the old's name
        gl::Framebuffer readFbo;          // the UI's
        std::uint64_t readGeneration = 0; // of the texture readFbo holds (0: none)
    };
    // A job the UI waits for, besides frames.
    enum class Job { None, Shaders, Capture };

    void warmCopies(); // UI
    void run();
    void runJob(Job job);
    // Returns whether it rendered the scene (else it only drew the last picture again). A
    // `poll` (no request asked for it) does nothing unless the view would render.
    bool step(const ViewFrameRequest& request, std::uint64_t serial, bool poll);
    // Thread: what the UI's next update() sets its scene message to.
    void publishSceneError(std::string message);
    // UI: posts `job` and waits for the thread to finish it.
    void waitForJob(Job job);
    // Thread: a slot to draw into, waited for (outside `submitting`, the held glSubmissionMutex()).
    int drawSlot(int width, int height, std::unique_lock<std::mutex>& submitting);

    std::unique_ptr<Window> threadWindow_;
    std::unique_ptr<Window> warmerWindow_;
    std::string startError_;
    // Made on the UI thread (no GL there), used and destroyed on the render thread.
    std::unique_ptr<ViewRenderer> view_;
    editor::AdaptiveScale adaptive_; // the thread's
    editor::ScenePreparingJob preparing_;
    std::uint64_t requestedRevision_ = 0;        // UI: the newest revision asked to be compiled
    std::optional<ViewFrameRequest> lastPosted_; // UI

    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<ViewFrameRequest> pending_; // the newest request not yet taken
    std::optional<CompiledScene> compiled_;   // the newest compiled scene not yet taken
    std::uint64_t posted_ = 0, done_ = 0;     // requests posted and finished
    int uiFrame_ = 0;                         // the UI's newest frame
    std::uint64_t uiFramesDone_ = 0;          // frames the UI has swapped
    Job job_ = Job::None;                     // the job the UI waits for, while it does
    bool jobTaken_ = false, jobDone_ = false;
    ShaderFiles shaderFiles_; // for Job::Shaders
    ViewInput captureView_;   // for Job::Capture
    int captureWidth_ = 0, captureHeight_ = 0;
    std::optional<Pixels<std::uint8_t>> captured_;
    bool jobOk_ = false;
    std::string jobError_;
    bool stopping_ = false;
    std::array<Slot, 3> slots_;
    int shownSlot_ = -1; // the newest finished picture, -1 before the first
    bool hasShaders_ = false;
    std::shared_ptr<const PreparedScene> drawnPublished_;
    ViewStatus status_;
    bool refined_ = false;
    bool refining_ = false;             // the thread goes on refining without a new request
    std::string sceneError_;            // the thread's last word on it
    std::uint64_t sceneErrorStamp_ = 0; // changes each time the thread sets it
    std::uint64_t sceneErrorSeen_ = 0;  // UI: the stamp last copied
    std::shared_ptr<const PreparedScene> newest_, drawn_; // UI: as last taken

    std::thread thread_; // last: starts once the rest is initialised
};

} // namespace rmsc::app
