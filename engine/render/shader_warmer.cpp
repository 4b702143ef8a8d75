// The background shader builder (see shader_warmer.hpp): one thread, one context, one request
// at a time.
#include "render/shader_warmer.hpp"

#include <algorithm>
#include <chrono>
#include <exception>

namespace rmsc {

namespace {

// Keeps the sets of built maps small; a map dropped from them is only built again.
constexpr std::size_t kMaxRemembered = 32;
// The warmer's frame: big enough for every pass to run, small enough to cost nothing.
constexpr int kWarmFrameSize = 8;

// The scene's settings with its march ended where it starts and every other loop cut to one
// turn. Step counts and distances are uniforms, so the programs are the ones the view draws
// with; only their first draw's work goes. llvmpipe rasterizes the draws of all contexts in
// one queue: the interpreter's full march of the 10,000-shape grid, even in this 8x8 frame,
// held it 50 to 65 ms, and the UI's frame queued behind it waited as long.
RenderSettings warmingSettings(RenderSettings settings) {
    settings.maxSteps = 1;
    settings.maxDistance = 1e-6f;
    settings.shadows.steps = 1;
    settings.ao.samples = std::min(settings.ao.samples, 1);
    return settings;
}

} // namespace

ShaderWarmer::ShaderWarmer(ContextBinder bindContext, ShaderFiles files)
    : thread_([this, bind = std::move(bindContext), f = std::move(files)]() mutable {
          run(std::move(bind), std::move(f));
      }) {}

ShaderWarmer::~ShaderWarmer() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        pending_.reset();
    }
    changed_.notify_all();
    thread_.join();
}

void ShaderWarmer::request(std::shared_ptr<const PreparedScene> scene,
                           const std::vector<std::string>& sdfMaps) {
    {
        std::lock_guard lock(mutex_);
        if (stopping_) return;
        const ShadingCode shading = sceneShading(*scene);
        std::deque<std::string> wanted;
        for (const std::string& map : sdfMaps) {
            const std::string key = sdfProgramsKey(shading, map);
            if (!warm_.contains(key) && !failed_.contains(key) && building_ != key)
                wanted.push_back(map);
        }
        if (pending_ && pending_->sdfMaps == wanted && sceneShading(*pending_->scene) == shading)
            return; // the scene too: same structure, same shading
        // A new request: the map being built counts in, as it finishes first.
        progressDone_ = 0;
        progressTotal_ = int(wanted.size()) + (building_.empty() ? 0 : 1);
        if (wanted.empty())
            pending_.reset();
        else
            pending_ = Request{std::move(scene), std::move(wanted)};
    }
    changed_.notify_all();
}

bool ShaderWarmer::isWarm(const ShadingCode& shading, const std::string& sdfMap) const {
    std::lock_guard lock(mutex_);
    return warm_.contains(sdfProgramsKey(shading, sdfMap));
}

bool ShaderWarmer::idle() const {
    std::lock_guard lock(mutex_);
    return !starting_ && !pending_ && building_.empty();
}

void ShaderWarmer::waitUntilIdle() const {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !starting_ && !pending_ && building_.empty(); });
}

std::string ShaderWarmer::takeError() {
    std::lock_guard lock(mutex_);
    return std::exchange(error_, {});
}

std::size_t ShaderWarmer::finishedCount() const {
    std::lock_guard lock(mutex_);
    return finished_;
}

ShaderWarmer::Progress ShaderWarmer::progress() const {
    std::lock_guard lock(mutex_);
    if (progressTotal_ <= 0 || (building_.empty() && !pending_)) return {};
    const double seconds =
        building_.empty()
            ? 0.0
            : std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart_).count();
    return {std::min(progressDone_, progressTotal_), progressTotal_, seconds};
}

double ShaderWarmer::buildMs(const ShadingCode& shading, const std::string& sdfMap) const {
    std::lock_guard lock(mutex_);
    const auto found = warm_.find(sdfProgramsKey(shading, sdfMap));
    return found == warm_.end() ? 0.0 : found->second;
}

void ShaderWarmer::run(ContextBinder bindContext, ShaderFiles files) {
    std::string error;
    const std::function<void()> release = bindContext(error);
    std::optional<Renderer> renderer;
    if (release) renderer = Renderer::create(std::move(files), error);
    if (!renderer) {
        std::lock_guard lock(mutex_);
        error_ = "shaders are not built in the background: " + error;
        stopping_ = true; // requests are ignored from now on
        starting_ = false;
        pending_.reset();
        changed_.notify_all();
        if (release) release();
        return;
    }
    std::optional<FrameTargets> targets = createFrameTargets(kWarmFrameSize, kWarmFrameSize);
    {
        std::lock_guard lock(mutex_);
        starting_ = false;
    }
    changed_.notify_all();
    for (;;) {
        std::shared_ptr<const PreparedScene> scene;
        std::string sdfMap;
        std::string key; // sdfProgramsKey
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
            if (stopping_) break;
            sdfMap = std::move(pending_->sdfMaps.front());
            pending_->sdfMaps.pop_front();
            scene = pending_->scene;
            if (pending_->sdfMaps.empty()) pending_.reset();
            // (The frame below is shaded as the scene's own settings say: warmingSettings keeps
            // what turns shading code on or off.)
            key = sdfProgramsKey(sceneShading(*scene), sdfMap);
            building_ = key;
            buildStart_ = std::chrono::steady_clock::now();
        }
        const auto start = std::chrono::steady_clock::now();
        std::string failure;
        try {
            // A map's shaders do not depend on the scene's cells: a grid of none, whose points
            // run an empty list, warms them without pruning the scene (seconds for thousands
            // of shapes, which the viewer's own pruning does meanwhile).
            SdfCellGrid noCells;
            noCells.code = scene->sdf.instructions;
            GpuScene gpu = uploadScene(*scene, SdfStrategy::Buffer, &noCells);
            gpu.sdfMap = sdfMap;
            renderer->render(gpu, scene->scene.camera, warmingSettings(scene->scene.render),
                             *targets);
            glFinish(); // the draws, where the driver finishes the programs
            // What the driver built is in its shader cache now; this context's own copy of it
            // (llvmpipe: the machine code, tens of megabytes for a few maps) is never drawn with.
            renderer->forgetScenePrograms();
        } catch (const std::exception& e) {
            failure = e.what();
        }
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        {
            std::lock_guard lock(mutex_);
            if (failure.empty()) {
                if (warm_.size() >= kMaxRemembered) warm_.clear();
                warm_[key] = ms;
            } else {
                if (failed_.size() >= kMaxRemembered) failed_.clear();
                failed_.insert(key);
                error_ = "a background shader build failed: " + failure;
            }
            ++finished_;
            ++progressDone_;
            if (!pending_) progressDone_ = progressTotal_ = 0; // the request is done
            building_.clear();
        }
        changed_.notify_all();
    }
    targets.reset(); // GL objects go while their context is current
    renderer.reset();
    release();
}

} // namespace rmsc
