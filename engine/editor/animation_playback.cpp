// Playing a glTF animation (see animation_playback.hpp).
#include "editor/animation_playback.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

double startPlayback(AnimationPlayback& playback, int mesh, double time, double duration) {
    playback.playing = true;
    playback.mesh = mesh;
    if (!(duration > 0.0)) return 0.0;
    if (time >= duration || time < 0.0)
        return playback.loop ? std::fmod(std::max(time, 0.0), duration) : 0.0;
    return time;
}

void pausePlayback(AnimationPlayback& playback) {
    playback.playing = false;
}

double advancePlayback(AnimationPlayback& playback, double time, double elapsed, double duration) {
    if (!playback.playing) return time;
    if (!(duration > 0.0)) return 0.0;
    const double next = time + std::max(elapsed, 0.0) * playback.speed;
    if (next < duration) return next;
    if (playback.loop) return std::fmod(next, duration);
    playback.playing = false;
    return duration;
}

} // namespace rmsc::editor
