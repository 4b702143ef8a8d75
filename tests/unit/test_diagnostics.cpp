// Diagnostics formatting: the message users see for every bad input.
#include "core/diagnostics.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rmsc;

TEST(Diagnostics, FormatsFilePointerAndMessage) {
    Diagnostics d;
    d.error("scene.json", "/sdf/children/3/radius", "expected a number >= 0, got -1");
    d.warning("scene.json", "/camera/fovv", "unknown key; did you mean \"fov\"?");
    EXPECT_EQ(d.errorCount(), 1);
    EXPECT_TRUE(d.hasErrors());
    EXPECT_EQ(d.format(),
              "scene.json: /sdf/children/3/radius: expected a number >= 0, got -1\n"
              "scene.json: /camera/fovv: warning: unknown key; did you mean \"fov\"?\n");
}

TEST(Diagnostics, WarningsAloneAreNotErrors) {
    Diagnostics d;
    d.warning("a.json", "", "something odd");
    EXPECT_FALSE(d.hasErrors());
}

TEST(Diagnostics, KeepsTheFirstHundredAndCountsEveryOne) {
    Diagnostics d;
    for (int i = 0; i < 250; ++i)
        d.error("a.json", "/x/" + std::to_string(i), "bad");
    for (int i = 0; i < 50; ++i)
        d.warning("a.json", "/y/" + std::to_string(i), "odd");
    EXPECT_EQ(d.items.size(), std::size_t(limits::kDiagnosticsKept));
    EXPECT_EQ(d.errorCount(), 250);
    EXPECT_EQ(d.warnings, 50);
    EXPECT_EQ(d.omittedErrors(), 150);
    EXPECT_EQ(d.omittedWarnings(), 50);
    EXPECT_FALSE(d.keeps());
    EXPECT_EQ(d.items.back().location, "/x/99");
    const std::string text = d.format();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), limits::kDiagnosticsKept + 1);
    EXPECT_TRUE(text.ends_with("a.json: /x/99: bad\n... and 150 more errors and 50 more warnings "
                               "(not shown; only the first 100 are)\n"))
        << text.substr(text.size() - 200);
}

TEST(Diagnostics, OmittedCountsCarryOverToAnotherList) {
    Diagnostics mesh;
    for (int i = 0; i < 101; ++i)
        mesh.warning("m.gltf", "", "w");
    mesh.error("m.gltf", "", "e"); // counted, not kept
    Diagnostics scene;
    for (const Diagnostic& item : mesh.items)
        scene.add(item);
    scene.addOmitted(mesh.omittedErrors(), mesh.omittedWarnings());
    EXPECT_TRUE(scene.hasErrors());
    EXPECT_EQ(scene.errorCount(), 1);
    EXPECT_EQ(scene.warnings, 101);
    EXPECT_TRUE(scene.format().ends_with("... and 1 more error and 1 more warning (not shown; "
                                         "only the first 100 are)\n"));
}
