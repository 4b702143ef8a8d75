// The editor's choice of SDF map (editor/editing_map.hpp): the best of the maps that are ready,
// the others to build; the interpreter only for scenes too large for generated code.
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

// The best ready map is drawn, baked (selection live) before buffer before interpreter; the
// rest is built in the same order; nothing ready draws nothing new.
TEST(EditingMap, TheBestReadyMapIsDrawnAndTheOthersBuilt) {
    const SdfProgram program = test::compileSdfText(kScene);
    const SdfLiveRange box{kSdfIdBase + 2, kSdfIdBase + 2};
    const std::string baked = generateSdfMap(program, SdfStrategy::Baked, {}, box);
    const std::string buffer = generateSdfMap(program, SdfStrategy::Buffer);
    const std::string interpreter = generateSdfMap(program, SdfStrategy::Interpreter);
    std::set<std::string> ready;
    auto isReady = [&](const std::string& map) { return ready.contains(map); };
    using Kind = editor::EditingMapKind;

    const editor::EditingMaps none = editor::chooseEditingMaps(program, program, box, isReady);
    EXPECT_EQ(none.draw, "") << "nothing is ready: the picture on screen stays";
    EXPECT_EQ(none.build, (std::vector<std::string>{baked, buffer, interpreter}));

    ready.insert(interpreter); // what a structural edit finds: the kinds did not change
    const editor::EditingMaps structural =
        editor::chooseEditingMaps(program, program, box, isReady);
    EXPECT_EQ(structural.draw, interpreter);
    EXPECT_EQ(structural.kind, Kind::Interpreter);
    EXPECT_EQ(structural.build, (std::vector<std::string>{baked, buffer}));

    ready.insert(buffer);
    const editor::EditingMaps buffered = editor::chooseEditingMaps(program, program, box, isReady);
    EXPECT_EQ(buffered.draw, buffer);
    EXPECT_EQ(buffered.kind, Kind::Buffer);
    EXPECT_EQ(buffered.build, std::vector<std::string>{baked});

    ready.insert(baked);
    const editor::EditingMaps best = editor::chooseEditingMaps(program, program, box, isReady);
    EXPECT_EQ(best.draw, baked);
    EXPECT_EQ(best.kind, Kind::Baked);
    EXPECT_TRUE(best.build.empty());

    // Another selection is another baked map, not built yet: the buffer map draws meanwhile.
    const SdfLiveRange sphere{kSdfIdBase + 1, kSdfIdBase + 1};
    const editor::EditingMaps other = editor::chooseEditingMaps(program, program, sphere, isReady);
    EXPECT_EQ(other.draw, buffer);
    ASSERT_EQ(other.build.size(), 1u);
    EXPECT_NE(other.build[0], baked);

    // A structural edit (a third shape) of the same kinds: only the interpreter is ready.
    const SdfProgram grown = test::compileSdfText(R"({"children": [
        {"shape": "sphere", "radius": 0.5}, {"shape": "box", "size": [1, 1, 1]},
        {"shape": "sphere", "radius": 0.2, "position": [0, 2, 0]}]})");
    const editor::EditingMaps edited = editor::chooseEditingMaps(grown, grown, box, isReady);
    EXPECT_EQ(edited.draw, interpreter) << "the interpreter's text names no instruction count";
    EXPECT_EQ(edited.kind, Kind::Interpreter);
    EXPECT_EQ(edited.build.size(), 2u);

    // The interpreter's map is that of the program the interpreter runs (the one with the
    // bounding hierarchy in the editor), the generated maps those of the other.
    const SdfProgram torus = test::compileSdfText(R"({"shape": "torus"})");
    const editor::EditingMaps split = editor::chooseEditingMaps(
        program, torus, box, [&](const std::string& map) { return map != baked; });
    EXPECT_EQ(split.draw, buffer);
    EXPECT_EQ(split.build, std::vector<std::string>{baked});
    const editor::EditingMaps interpreted =
        editor::chooseEditingMaps(program, torus, box, [&](const std::string& map) {
            return map.find("strategy interpreter") != std::string::npos;
        });
    EXPECT_EQ(interpreted.draw, generateSdfMap(torus, SdfStrategy::Interpreter));
    EXPECT_NE(interpreted.draw, interpreter);
}

TEST(EditingMap, ScenesTooLargeForGeneratedCodeHaveTheCellsMapThenTheInterpreter) {
    std::string children;
    for (int i = 0; i <= kMaxGeneratedLeaves; ++i)
        children += std::string(i ? ", " : "") + R"({"shape": "sphere", "radius": 0.1})";
    const SdfProgram large = test::compileSdfText(R"({"children": [)" + children + "]}");
    const std::string cells = generateSdfMap(large, SdfStrategy::Cells);
    const std::string interpreter = generateSdfMap(large, SdfStrategy::Interpreter);
    ASSERT_NE(cells, interpreter);
    const editor::EditingMaps maps = editor::chooseEditingMaps(
        large, large, {kSdfIdBase + 1, kSdfIdBase + 1}, [](const std::string&) { return false; });
    EXPECT_EQ(maps.draw, "");
    EXPECT_EQ(maps.build, (std::vector<std::string>{cells, interpreter}));
    const editor::EditingMaps ready = editor::chooseEditingMaps(
        large, large, {kSdfIdBase + 1, kSdfIdBase + 1}, [](const std::string&) { return true; });
    EXPECT_EQ(ready.draw, cells);
    EXPECT_EQ(ready.kind, editor::EditingMapKind::Cells);
    EXPECT_TRUE(ready.build.empty()) << "nothing to build in the background";
    // Until the cells map is built, the interpreter draws.
    const editor::EditingMaps fallback = editor::chooseEditingMaps(
        large, large, {}, [&](const std::string& map) { return map == interpreter; });
    EXPECT_EQ(fallback.draw, interpreter);
    EXPECT_EQ(fallback.build, std::vector<std::string>{cells});
}

// A grid whose postfix lists are all short has the cells map that reads one instruction per
// loop iteration first, then the one for any grid, built too and drawn until the first is ready
// (and after an edit that makes a list long); a grid with a long list has only the second, and
// so does a union of shapes (the lean loop, one text). A grid whose stacks are shallow too has
// the text that fits both first; a deeper grid never draws that one, ready or not.
TEST(EditingMap, ShortListsHaveTheirOwnCellsMapThenTheOneForAnyGrid) {
    std::string children;
    for (int i = 0; i <= kMaxGeneratedLeaves; ++i)
        children += std::string(i ? ", " : "") + R"({"shape": "sphere", "radius": 0.1})";
    const SdfProgram large = test::compileSdfText(
        R"({"op": "smooth_union", "smoothness": 0.1, "children": [)" + children + "]}");
    ASSERT_EQ(effectiveSdfStrategy(large, SdfStrategy::Baked), SdfStrategy::Cells);
    const SdfProgram lean = test::compileSdfText(R"({"children": [)" + children + "]}");
    const std::string leanMap = generateSdfMap(lean, SdfStrategy::Cells);
    ASSERT_NE(leanMap.find("SDF_CELLS_LEAN"), std::string::npos);
    EXPECT_EQ(generateSdfMap(lean, SdfStrategy::Cells, {}, {}, SdfCellFit{.shortLists = true}),
              leanMap);
    const editor::EditingMaps leanMaps = editor::chooseEditingMaps(
        lean, lean, {}, [](const std::string&) { return false; }, SdfCellFit{.shortLists = true});
    EXPECT_EQ(leanMaps.build,
              (std::vector<std::string>{leanMap, generateSdfMap(lean, SdfStrategy::Interpreter)}));
    const std::string anyGrid = generateSdfMap(large, SdfStrategy::Cells);
    const std::string shortLists =
        generateSdfMap(large, SdfStrategy::Cells, {}, {}, SdfCellFit{.shortLists = true});
    const std::string interpreter = generateSdfMap(large, SdfStrategy::Interpreter);
    EXPECT_EQ(anyGrid.find("SDF_CELLS_SHORT_LISTS"), std::string::npos);
    EXPECT_NE(shortLists.find("SDF_CELLS_SHORT_LISTS"), std::string::npos);
    auto none = [](const std::string&) { return false; };
    const editor::EditingMaps building =
        editor::chooseEditingMaps(large, large, {}, none, SdfCellFit{.shortLists = true});
    EXPECT_EQ(building.draw, "");
    EXPECT_EQ(building.build, (std::vector<std::string>{shortLists, anyGrid, interpreter}));
    const editor::EditingMaps meanwhile = editor::chooseEditingMaps(
        large, large, {}, [&](const std::string& map) { return map == anyGrid; },
        SdfCellFit{.shortLists = true});
    EXPECT_EQ(meanwhile.draw, anyGrid);
    EXPECT_EQ(meanwhile.kind, editor::EditingMapKind::Cells);
    EXPECT_EQ(meanwhile.build, (std::vector<std::string>{shortLists, interpreter}));
    const editor::EditingMaps ready = editor::chooseEditingMaps(
        large, large, {}, [](const std::string&) { return true; }, SdfCellFit{.shortLists = true});
    EXPECT_EQ(ready.draw, shortLists);
    const editor::EditingMaps longLists = editor::chooseEditingMaps(
        large, large, {}, [](const std::string&) { return true; }, SdfCellFit{});
    EXPECT_EQ(longLists.draw, anyGrid);

    // Shallow stacks too: the text for a grid that fits both, which a deeper grid never gets.
    const SdfCellFit both{.shortLists = true, .shallowStacks = true};
    const std::string fitted = generateSdfMap(large, SdfStrategy::Cells, {}, {}, both);
    EXPECT_NE(fitted.find("SDF_CELLS_SHORT_LISTS"), std::string::npos);
    EXPECT_NE(fitted.find("SDF_CELLS_SHALLOW_STACKS"), std::string::npos);
    EXPECT_EQ(shortLists.find("SDF_CELLS_SHALLOW_STACKS"), std::string::npos);
    EXPECT_EQ(anyGrid.find("SDF_CELLS_SHALLOW_STACKS"), std::string::npos);
    EXPECT_EQ(generateSdfMap(lean, SdfStrategy::Cells, {}, {}, both), leanMap); // (no stack)
    auto all = [](const std::string&) { return true; };
    EXPECT_EQ(editor::chooseEditingMaps(large, large, {}, all, both).draw, fitted);
    const editor::EditingMaps deeper = editor::chooseEditingMaps(
        large, large, {}, [&](const std::string& map) { return map != shortLists; },
        SdfCellFit{.shortLists = true});
    EXPECT_EQ(deeper.draw, anyGrid); // (the shallow text is ready, and not for this grid)
    EXPECT_EQ(deeper.build, (std::vector<std::string>{shortLists}));
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
