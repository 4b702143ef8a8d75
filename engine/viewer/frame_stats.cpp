// The viewer's frame statistics (see frame_stats.hpp).
#include "frame_stats.hpp"

#include <algorithm>
#include <cstdio>

namespace rmsc::app {

std::optional<std::string> recordFrame(FrameStats& stats, const ViewStatus& status, int frame,
                                       float milliseconds, float targetMilliseconds, double now,
                                       double lastInput) {
    ++stats.allFrames;
    stats.allMaxMilliseconds = std::max(stats.allMaxMilliseconds, milliseconds);
    stats.allSumMilliseconds += milliseconds;
    if (milliseconds > targetMilliseconds) {
        ++stats.overTarget;
        if (stats.overTargetFrames.size() < std::size_t(FrameStats::kOverTargetListed))
            stats.overTargetFrames.emplace_back(frame, milliseconds);
    }
    if (status.changes != stats.changes) { // this frame showed a change: count from it
        stats.changes = status.changes;
        stats.frames = 0;
        stats.maxMilliseconds = 0.0f;
        stats.sumMilliseconds = 0.0;
    }
    ++stats.frames;
    stats.maxMilliseconds = std::max(stats.maxMilliseconds, milliseconds);
    stats.sumMilliseconds += milliseconds;
    if (status.refinements == stats.refinements || !status.refined) return std::nullopt;
    stats.refinements = status.refinements;
    char line[256];
    std::snprintf(line, sizeof line,
                  "frame %d: refined %dx%d in %d frames, %.0f ms after the last input; UI frames "
                  "since the change: longest %.1f ms, mean %.1f ms",
                  frame, status.width, status.height, stats.frames,
                  std::max(0.0, now - lastInput) * 1000.0, stats.maxMilliseconds,
                  stats.sumMilliseconds / stats.frames);
    return std::string(line);
}

void recordSceneWork(FrameStats& stats, int frame, float milliseconds, bool waitedForCompile) {
    if (waitedForCompile && stats.firstCompileWaitFrame < 0) stats.firstCompileWaitFrame = frame;
    if (milliseconds <= stats.longestSceneMilliseconds) return;
    stats.longestSceneMilliseconds = milliseconds;
    stats.longestSceneFrame = frame;
}

std::string frameSummary(const FrameStats& stats, float targetMilliseconds) {
    char line[320];
    std::snprintf(line, sizeof line,
                  "opening frame %.1f ms (drawn before the window was shown); UI frames: %d, "
                  "longest %.1f ms, mean %.1f ms, %d over the %.0f ms target; "
                  "longest scene update %.1f ms (frame %d)",
                  stats.openingMilliseconds, stats.allFrames, stats.allMaxMilliseconds,
                  stats.allFrames ? stats.allSumMilliseconds / stats.allFrames : 0.0,
                  stats.overTarget, targetMilliseconds, stats.longestSceneMilliseconds,
                  stats.longestSceneFrame);
    std::string summary(line);
    if (stats.firstCompileWaitFrame >= 0)
        std::snprintf(line, sizeof line, "; first wait for a compile: frame %d",
                      stats.firstCompileWaitFrame);
    else
        std::snprintf(line, sizeof line, "; no wait for a compile");
    summary += line;
    for (std::size_t i = 0; i < stats.overTargetFrames.size(); ++i) {
        std::snprintf(line, sizeof line, "%s frame %d %.1f ms", i == 0 ? "; over:" : ",",
                      stats.overTargetFrames[i].first, stats.overTargetFrames[i].second);
        summary += line;
    }
    if (stats.overTarget > int(stats.overTargetFrames.size())) summary += ", ...";
    return summary;
}

} // namespace rmsc::app
