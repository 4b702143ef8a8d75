// Builds a scene's shader programs in the background, on a second GL context on a thread of its
// own, so the thread that draws never waits for a compile it can do without.
//
// The warmer draws one small frame of the scene with the requested SDF map through its own
// Renderer. That is the whole compile: drivers finish programs at their first draw (llvmpipe
// generates its machine code there), and keep what they built in their shader cache (Mesa's on
// disk), so when the main context then builds the same program it takes tens of milliseconds
// instead of seconds. The editor asks it for the maps it would rather draw than the one it has
// (editor/editing_map.hpp) and draws what it has until they are warm.
//
// A request is a list of maps built one after the other. Requests replace each other: only the
// newest list waits, and the map being built finishes. A driver without a shader cache still
// works, the main context then compiles as it always did.
#pragma once

#include "prepare/prepared_scene.hpp"
#include "render/renderer.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace rmsc {

class ShaderWarmer {
  public:
    // Makes a GL 4.5 context current on the calling thread (the warmer's) and returns what
    // releases it when the thread ends, or nullptr with `error` set when there is none.
    using ContextBinder = std::function<std::function<void()>(std::string& error)>;

    ShaderWarmer(ContextBinder bindContext, ShaderFiles files);
    ~ShaderWarmer(); // finishes the program being built, drops the rest
    ShaderWarmer(const ShaderWarmer&) = delete;
    ShaderWarmer& operator=(const ShaderWarmer&) = delete;

    // Builds the programs of `scene` uploaded with its SDF map replaced by each of `sdfMaps` in
    // turn (the shells' maps are the buffer strategy's, as the editor draws them), skipping maps
    // that are warm, failed or being built. Replaces what is waiting.
    // The scene is shared, not copied: the caller's thread never waits for a copy of it.
    void request(std::shared_ptr<const PreparedScene> scene,
                 const std::vector<std::string>& sdfMaps);
    // Has a request for this map with this shading code (a scene's sceneShading) finished
    // building?
    bool isWarm(const ShadingCode& shading, const std::string& sdfMap) const;
    // How many maps have finished building (or failed) since the start: changes when there may be
    // a better map to draw.
    std::size_t finishedCount() const;
    // Started (or failed to), nothing waiting and nothing being built.
    bool idle() const;
    // Waits until idle (for scripted runs and tests).
    void waitUntilIdle() const;
    // Why the warmer stopped (no context, or a map that did not build), once; empty if it runs.
    std::string takeError();
    // Milliseconds a warm map took to build (0 when it is not warm).
    double buildMs(const ShadingCode& shading, const std::string& sdfMap) const;

    // How far the current request has come: the maps of it built (or failed) and how many it
    // has (the one being built when it was made counts in), and the seconds the map being built
    // has taken so far (0 before the thread takes it up). All 0 when nothing waits or builds.
    struct Progress {
        int done = 0;
        int total = 0;
        double seconds = 0.0;
    };
    Progress progress() const;

  private:
    struct Request {
        std::shared_ptr<const PreparedScene> scene; // one copy for all its maps
        std::deque<std::string> sdfMaps;            // first first
    };
    void run(ContextBinder bindContext, ShaderFiles files);

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::optional<Request> pending_;
    // By sdfProgramsKey (render/renderer.hpp): a map with the shading code of its scene.
    std::string building_;               // the programs being built, "" when none
    std::map<std::string, double> warm_; // programs, milliseconds their build took
    std::set<std::string> failed_;
    std::string error_;
    std::size_t finished_ = 0;
    int progressDone_ = 0, progressTotal_ = 0;         // of the current request (see progress())
    std::chrono::steady_clock::time_point buildStart_; // of the map being built
    bool starting_ = true; // the thread is making its context current and its renderer
    bool stopping_ = false;
    std::thread thread_; // last: starts once the rest is initialised
};

} // namespace rmsc
