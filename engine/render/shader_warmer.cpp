// The background shader builder (see shader_warmer.hpp): one thread, one context, one request
// at a time.
#include "render/shader_warmer.hpp"

#include <chrono>
#include <exception>

namespace rmsc {

namespace {

// Keeps the sets of built maps small; a map dropped from them is only built again.
constexpr std::size_t kMaxRemembered = 32;
// The warmer's frame: big enough for every pass to run, small enough to cost nothing.
constexpr int kWarmFrameSize = 8;

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

void ShaderWarmer::request(const PreparedScene& scene, const std::string& sdfMap) {
    {
        std::lock_guard lock(mutex_);
        if (stopping_ || warm_.contains(sdfMap) || failed_.contains(sdfMap) ||
            building_ == sdfMap || (pending_ && pending_->sdfMap == sdfMap))
            return;
        pending_ = Request{scene, sdfMap};
    }
    changed_.notify_all();
}

bool ShaderWarmer::isWarm(const std::string& sdfMap) const {
    std::lock_guard lock(mutex_);
    return warm_.contains(sdfMap);
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

double ShaderWarmer::lastWarmMs() const {
    std::lock_guard lock(mutex_);
    return lastWarmMs_;
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
        Request request;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
            if (stopping_) break;
            request = std::move(*pending_);
            pending_.reset();
            building_ = request.sdfMap;
        }
        const auto start = std::chrono::steady_clock::now();
        std::string failure;
        try {
            GpuScene gpu = uploadScene(request.scene, SdfStrategy::Buffer);
            gpu.sdfMap = request.sdfMap;
            renderer->render(gpu, request.scene.scene.camera, request.scene.scene.render, *targets);
            glFinish(); // the draws, where the driver finishes the programs
        } catch (const std::exception& e) {
            failure = e.what();
        }
        {
            std::lock_guard lock(mutex_);
            std::set<std::string>& done = failure.empty() ? warm_ : failed_;
            if (done.size() >= kMaxRemembered) done.clear();
            done.insert(request.sdfMap);
            if (!failure.empty()) error_ = "a background shader build failed: " + failure;
            building_.clear();
            lastWarmMs_ =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
        }
        changed_.notify_all();
    }
    targets.reset(); // GL objects go while their context is current
    renderer.reset();
    release();
}

} // namespace rmsc
