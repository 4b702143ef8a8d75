// Scene files built to cost time or output out of proportion to their size: objects with
// hundreds of thousands of keys (linear to parse and check), as many duplicates, thousands of
// errors (kept to the first 100, all counted), huge lists of names in messages, and camera
// vectors whose float arithmetic overflows.
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace rmsc;

namespace {

// {"version": 1, <members>}
std::string sceneWith(const std::string& members) {
    return "{\"version\": 1, " + members + "}";
}

std::string manyKeys(int count, int distinct) {
    std::string out;
    for (int i = 0; i < count; ++i)
        out += (i ? ", \"k" : "\"k") + std::to_string(i % distinct) + "\": " + std::to_string(i);
    return out;
}

} // namespace

TEST(HostileScenes, ObjectWith200000UnknownKeysIsReadWithCappedWarnings) {
    Diagnostics d;
    const auto scene = parseScene(sceneWith(manyKeys(200000, 200000)), "keys.json", d);
    ASSERT_TRUE(scene) << d.format().substr(0, 2000);
    EXPECT_EQ(d.warnings, 200000);
    EXPECT_EQ(d.items.size(), std::size_t(limits::kDiagnosticsKept));
    EXPECT_EQ(d.items.front().location, "/k0");
    EXPECT_EQ(d.items.back().location, "/k99");
    const std::string text = d.format();
    EXPECT_LT(text.size(), 40000u);
    EXPECT_NE(text.find("\n... and 199900 more warnings (not shown; only the first 100 are)\n"),
              std::string::npos)
        << text.substr(text.size() - 300);
}

TEST(HostileScenes, EveryDuplicateKeyIsCountedAndTheLastValueKept) {
    Diagnostics d;
    // 100000 keys, each twice, in the camera; then a duplicate "fov" whose last value counts.
    const auto scene = parseScene(
        sceneWith("\"camera\": {\"fov\": 10, " + manyKeys(200000, 100000) + ", \"fov\": 30}"),
        "dup.json", d);
    EXPECT_FALSE(scene);
    EXPECT_EQ(d.errors, 100001);
    EXPECT_EQ(d.items.front().location, "/camera/k0");
    EXPECT_EQ(d.items.front().message,
              "duplicate key \"k0\"; each key may appear once in an object");
    EXPECT_NE(d.format().find("... and 99901 more errors"), std::string::npos);

    Diagnostics once;
    const auto read = parseScene(
        sceneWith(R"("camera": {"fov": 10, "near": 0.5, "fov": 30, "far": 90})"), "dup.json", once);
    EXPECT_FALSE(read);
    ASSERT_EQ(once.errors, 1) << once.format();
    EXPECT_EQ(once.items[0].location, "/camera/fov");
}

TEST(HostileScenes, TwoThousandUnknownMaterialsGiveBoundedMessages) {
    std::string materials, children;
    for (int i = 0; i < 4096; ++i)
        materials += (i ? ", \"mat" : "\"mat") + std::to_string(1000 + i) + "\": {}";
    for (int i = 0; i < 2000; ++i)
        children += std::string(i ? ", " : "") + R"({"shape": "sphere", "material": "nosuch"})";
    Diagnostics d;
    EXPECT_FALSE(
        parseScene(sceneWith("\"materials\": {" + materials +
                             "}, \"sdf\": {\"op\": \"union\", \"children\": [" + children + "]}"),
                   "mat.json", d));
    EXPECT_EQ(d.errors, 2000);
    ASSERT_FALSE(d.items.empty());
    EXPECT_EQ(d.items[0].location, "/sdf/children/0/material");
    // The 4096 names are not all quoted: 64 of them, then how many more.
    EXPECT_NE(d.items[0].message.find("\"mat1063\" and 4032 more"), std::string::npos)
        << d.items[0].message.substr(0, 300);
    EXPECT_EQ(d.items[0].message.find("\"mat1064\""), std::string::npos);
    EXPECT_LT(d.format().size(), 100000u);
}

TEST(HostileScenes, CameraVectorsThatOverflowFloatsAreNamed) {
    Diagnostics view;
    EXPECT_FALSE(
        parseScene(sceneWith(R"("camera": {"position": [3e38, 0, 0], "target": [-3e38, 0, 0]})"),
                   "c.json", view));
    ASSERT_EQ(view.errors, 1) << view.format();
    EXPECT_EQ(view.items[0].location, "/camera/target");
    EXPECT_NE(view.items[0].message.find("too long for float arithmetic"), std::string::npos)
        << view.items[0].message;

    // 1e20 is a float, but its square is not: the view direction cannot be normalized.
    Diagnostics far;
    EXPECT_FALSE(parseScene(
        sceneWith(R"("camera": {"position": [1e20, 0, 0], "target": [0, 0, 0]})"), "c.json", far));
    ASSERT_EQ(far.errors, 1) << far.format();
    EXPECT_EQ(far.items[0].location, "/camera/target");

    Diagnostics up;
    EXPECT_FALSE(parseScene(
        sceneWith(
            R"("camera": {"position": [0, 0, 5], "target": [0, 0, 0], "up": [3e38, 3e38, 0]})"),
        "c.json", up));
    ASSERT_EQ(up.errors, 1) << up.format();
    EXPECT_EQ(up.items[0].location, "/camera/up");
    EXPECT_NE(up.items[0].message.find("too long for float arithmetic"), std::string::npos)
        << up.items[0].message;

    // A parallel up vector is still called that.
    Diagnostics parallel;
    EXPECT_FALSE(parseScene(
        sceneWith(R"("camera": {"position": [0, 5, 0], "target": [0, 0, 0], "up": [0, 1, 0]})"),
        "c.json", parallel));
    ASSERT_EQ(parallel.errors, 1);
    EXPECT_NE(parallel.items[0].message.find("not parallel"), std::string::npos);
}
