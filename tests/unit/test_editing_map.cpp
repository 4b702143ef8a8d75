// The editor's choice of SDF map (editor/editing_map.hpp): the buffer map until the baked map
// with the selection live is ready, then that one; the interpreter for scenes too large for
// generated code.
#include "editor/editing_map.hpp"
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"

#include "sdf_text.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace rmsc;

namespace {

const char* kScene = R"({"children": [{"shape": "sphere", "radius": 0.5},
    {"shape": "box", "size": [1, 1, 1], "position": [2, 0, 0]}]})";

} // namespace

TEST(EditingMap, BufferUntilTheBakedMapIsReadyThenBaked) {
    const SdfProgram program = test::compileSdfText(kScene);
    const SdfLiveRange box{kSdfIdBase + 2, kSdfIdBase + 2};
    std::set<std::string> ready;
    auto isReady = [&](const std::string& map) { return ready.contains(map); };

    const editor::EditingMaps before = editor::chooseEditingMaps(program, box, isReady);
    EXPECT_EQ(before.draw, generateSdfMap(program, SdfStrategy::Buffer));
    EXPECT_FALSE(before.baked);
    EXPECT_EQ(before.build, generateSdfMap(program, SdfStrategy::Baked, {}, box));

    ready.insert(before.build);
    const editor::EditingMaps after = editor::chooseEditingMaps(program, box, isReady);
    EXPECT_EQ(after.draw, before.build);
    EXPECT_TRUE(after.baked);
    EXPECT_TRUE(after.build.empty());

    // Another selection is another baked map, not built yet.
    const SdfLiveRange sphere{kSdfIdBase + 1, kSdfIdBase + 1};
    const editor::EditingMaps other = editor::chooseEditingMaps(program, sphere, isReady);
    EXPECT_FALSE(other.baked);
    EXPECT_NE(other.build, before.build);
    EXPECT_FALSE(other.build.empty());
}

TEST(EditingMap, ScenesTooLargeForGeneratedCodeKeepTheInterpreter) {
    std::string children;
    for (int i = 0; i <= kMaxGeneratedLeaves; ++i)
        children += std::string(i ? ", " : "") + R"({"shape": "sphere", "radius": 0.1})";
    const SdfProgram large = test::compileSdfText(R"({"children": [)" + children + "]}");
    const editor::EditingMaps maps = editor::chooseEditingMaps(
        large, {kSdfIdBase + 1, kSdfIdBase + 1}, [](const std::string&) { return true; });
    EXPECT_FALSE(maps.baked);
    EXPECT_TRUE(maps.build.empty()) << "nothing to build in the background";
    EXPECT_EQ(maps.draw, generateSdfMap(large, SdfStrategy::Interpreter));
}

// The live range is the selected node and its subtree, inclusive, and nothing for a selection
// that is no SDF node.
TEST(EditingMap, TheSelectionsSubtreeIsLive) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(R"({"version": 1, "sdf": {"children": [
        {"shape": "sphere"},
        {"children": [{"shape": "box"}, {"shape": "torus"}]},
        {"shape": "capsule"}]}})",
                                                  "t.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.format();
    // Pre-order: root 0, sphere 1, group 2, box 3, torus 4, capsule 5.
    const SdfLiveRange group = editor::selectionLiveRange(*scene, editor::Selection::sdf({1}));
    EXPECT_EQ(group.first, kSdfIdBase + 2);
    EXPECT_EQ(group.last, kSdfIdBase + 4);
    EXPECT_FALSE(group.contains(kSdfIdBase + 5)) << "the capsule is not in the group";
    const SdfLiveRange sphere = editor::selectionLiveRange(*scene, editor::Selection::sdf({0}));
    EXPECT_EQ(sphere.first, kSdfIdBase + 1);
    EXPECT_EQ(sphere.last, kSdfIdBase + 1);
    for (const editor::Selection& none : {editor::Selection::none(), editor::Selection::mesh(0)}) {
        const SdfLiveRange live = editor::selectionLiveRange(*scene, none);
        EXPECT_LT(live.last, live.first) << "empty";
        EXPECT_FALSE(live.contains(0));
    }
}
