// Two small parts of the viewer's model: the shader build's progress as the overlay shows it
// (editor/build_progress.hpp) and the panels' scale (editor/ui_scale.hpp).
#include "editor/build_progress.hpp"
#include "editor/ui_scale.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace rmsc::editor;

TEST(BuildProgress, FractionAndText) {
    const BuildProgress idle;
    EXPECT_EQ(buildProgressFraction(idle), 0.0f);
    EXPECT_EQ(buildProgressText(idle), "") << "nothing shows while nothing builds";
    const BuildProgress first{0, 3, 1.26, "better maps"};
    EXPECT_FLOAT_EQ(buildProgressFraction(first), 0.5f / 3.0f) << "half of the one under way";
    EXPECT_EQ(buildProgressText(first), "building shaders 1 of 3 (better maps), 1.3 s");
    const BuildProgress last{2, 3, 0.0, ""};
    EXPECT_FLOAT_EQ(buildProgressFraction(last), 2.5f / 3.0f);
    EXPECT_EQ(buildProgressText(last), "building shaders 3 of 3, 0.0 s");
    const BuildProgress over{5, 3, 0.0, ""};
    EXPECT_EQ(buildProgressFraction(over), 1.0f);
    EXPECT_EQ(buildProgressText(over), "building shaders 3 of 3, 0.0 s");
}

TEST(UiScale, OptionElseContentScaleWithinBounds) {
    EXPECT_EQ(uiScale(1.5f, 2.0f, 2.0f), 1.5f) << "--ui-scale wins";
    EXPECT_EQ(uiScale(0.0f, 2.0f, 1.5f), 2.0f) << "the larger content scale";
    EXPECT_EQ(uiScale(0.0f, 1.0f, 1.0f), 1.0f);
    EXPECT_EQ(uiScale(0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f), 1.0f);
    EXPECT_EQ(uiScale(0.0f, 9.0f, 9.0f), kMaxUiScale);
    EXPECT_EQ(uiScale(0.1f, 1.0f, 1.0f), kMinUiScale);
    EXPECT_EQ(uiScale(std::numeric_limits<float>::infinity(), 1.25f, 1.0f), 1.25f)
        << "an unusable option is none";
}
