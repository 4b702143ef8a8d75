// The viewer's animation playback (editor/animation_playback.hpp): the time advances by the
// frame's wall time while playing, wraps when looping, stops at the end otherwise, holds while
// paused; starting at the end of a clip that does not loop starts it over.
#include "editor/animation_playback.hpp"

#include <gtest/gtest.h>

using namespace rmsc::editor;

TEST(AnimationPlayback, AdvancesOnlyWhilePlaying) {
    AnimationPlayback playback;
    EXPECT_DOUBLE_EQ(advancePlayback(playback, 0.5, 0.1, 2.0), 0.5); // paused
    EXPECT_DOUBLE_EQ(startPlayback(playback, 3, 0.5, 2.0), 0.5);
    EXPECT_TRUE(playback.playing);
    EXPECT_EQ(playback.mesh, 3);
    double t = 0.5;
    for (int frame = 0; frame < 10; ++frame)
        t = advancePlayback(playback, t, 1.0 / 30.0, 2.0);
    EXPECT_NEAR(t, 0.5 + 10.0 / 30.0, 1e-12);
    pausePlayback(playback);
    EXPECT_FALSE(playback.playing);
    EXPECT_DOUBLE_EQ(advancePlayback(playback, t, 0.1, 2.0), t);
}

TEST(AnimationPlayback, LoopsOrStopsAtTheEnd) {
    AnimationPlayback looping;
    startPlayback(looping, 0, 1.9, 2.0);
    EXPECT_NEAR(advancePlayback(looping, 1.9, 0.25, 2.0), 0.15, 1e-12);
    EXPECT_TRUE(looping.playing);

    AnimationPlayback once;
    once.loop = false;
    startPlayback(once, 0, 1.9, 2.0);
    EXPECT_DOUBLE_EQ(advancePlayback(once, 1.9, 0.25, 2.0), 2.0);
    EXPECT_FALSE(once.playing) << "stops at the end";
    // Play again from the end: from the start.
    EXPECT_DOUBLE_EQ(startPlayback(once, 0, 2.0, 2.0), 0.0);
}

TEST(AnimationPlayback, SpeedAndDegenerateClips) {
    AnimationPlayback playback;
    playback.speed = 0.5;
    startPlayback(playback, 0, 0.0, 4.0);
    EXPECT_DOUBLE_EQ(advancePlayback(playback, 1.0, 1.0, 4.0), 1.5);
    EXPECT_DOUBLE_EQ(advancePlayback(playback, 1.0, -1.0, 4.0), 1.0) << "time never runs back";
    // A clip of one key lasts 0 s: the time stays at 0.
    EXPECT_DOUBLE_EQ(startPlayback(playback, 0, 0.7, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(advancePlayback(playback, 0.0, 0.5, 0.0), 0.0);
    // A time past the end of a looping clip starts within it.
    EXPECT_NEAR(startPlayback(playback, 0, 4.5, 4.0), 0.5, 1e-12);
}
