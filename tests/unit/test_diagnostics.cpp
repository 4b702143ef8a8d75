// Diagnostics formatting: the message users see for every bad input.
#include "core/diagnostics.hpp"

#include <gtest/gtest.h>

using namespace rmsc;

TEST(Diagnostics, FormatsFilePointerAndMessage) {
    Diagnostics d;
    d.error("scene.json", "/sdf/children/3/radius", "expected a number >= 0, got -1");
    d.warning("scene.json", "/camera/fovv", "unknown key; did you mean \"fov\"?");
    EXPECT_EQ(d.errorCount(), 1);
    EXPECT_TRUE(d.hasErrors());
    EXPECT_EQ(d.format(), "scene.json: /sdf/children/3/radius: expected a number >= 0, got -1\n"
                          "scene.json: /camera/fovv: warning: unknown key; did you mean \"fov\"?\n");
}

TEST(Diagnostics, WarningsAloneAreNotErrors) {
    Diagnostics d;
    d.warning("a.json", "", "something odd");
    EXPECT_FALSE(d.hasErrors());
}
