// What `rmsc view --stats` reports: the UI frame times of the frames after each change (from
// the one that shows the quick render to the one that completes the full-resolution image), the
// time from the last input to the refined image, and a summary of every frame at exit.
#pragma once

#include "view_renderer.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rmsc::app {

struct FrameStats {
    // The window's first frame, drawn before the window is shown (not a UI frame); < 0: none.
    float openingMilliseconds = -1.0f;
    // The renderer's counts as last seen (ViewStatus::changes, ::refinements).
    int changes = 0, refinements = 0;
    // Since the last change: frames, their longest and their total milliseconds.
    int frames = 0;
    float maxMilliseconds = 0.0f;
    double sumMilliseconds = 0.0;
    // Every frame.
    int allFrames = 0;
    float allMaxMilliseconds = 0.0f;
    double allSumMilliseconds = 0.0;
    int overTarget = 0; // frames longer than the target
    // The first kOverTargetListed of them: frame number and milliseconds (the summary names
    // them, so a long frame can be found in the log).
    static constexpr int kOverTargetListed = 12;
    std::vector<std::pair<int, float>> overTargetFrames;
    // The longest a frame spent handing the scene to the GPU side (compiling it, pruning its
    // cells, uploading it, building shaders it had to build there): work that blocks the frame.
    float longestSceneMilliseconds = 0.0f;
    int longestSceneFrame = -1;
    // The first frame that waited for the scene's compile (a small scene's, after an edit; never
    // the first frame, which draws on without it); -1: none.
    int firstCompileWaitFrame = -1;
};

// Records one UI frame that took `milliseconds` and showed `status`; returns the log line when it
// completed a refinement. `now` and `lastInput` are in seconds (glfwGetTime).
std::optional<std::string> recordFrame(FrameStats& stats, const ViewStatus& status, int frame,
                                       float milliseconds, float targetMilliseconds, double now,
                                       double lastInput);
// Records that frame `frame` spent `milliseconds` on the scene (see longestSceneMilliseconds),
// and whether it waited for the scene's compile.
void recordSceneWork(FrameStats& stats, int frame, float milliseconds, bool waitedForCompile);
// The line for every frame, at exit.
std::string frameSummary(const FrameStats& stats, float targetMilliseconds);

} // namespace rmsc::app
