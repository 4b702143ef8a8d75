// Playing a mesh's glTF animation in the viewer: play and pause, the time advancing by each
// frame's wall time while playing (looping over the animation's duration, or stopping at its
// end), and the timeline's range. The time played is the mesh's own "time" (what scrubbing and
// saving use), so a pause leaves the mesh where it stopped. GL-free.
#pragma once

namespace rmsc::editor {

struct AnimationPlayback {
    bool playing = false;
    bool loop = true;   // wrap to 0 past the end; otherwise stop at the end
    double speed = 1.0; // animation seconds per second of wall time (> 0)
    int mesh = -1;      // the mesh instance playing (scene.meshes index), -1 for none
};

// Starts playing mesh `mesh` from `time`: returns the time to start from (0 when `time` is at
// or past the end of a `duration`-second animation that does not loop, or past it when it does).
double startPlayback(AnimationPlayback& playback, int mesh, double time, double duration);

// Stops playing (the time stays where it is).
void pausePlayback(AnimationPlayback& playback);

// The time `elapsed` seconds of wall time after `time` while playing (`time` unchanged while
// paused): looping wraps it into [0, duration); otherwise it stops at `duration` and playback
// pauses. A duration of 0 (a single key) keeps the time at 0.
double advancePlayback(AnimationPlayback& playback, double time, double elapsed, double duration);

} // namespace rmsc::editor
