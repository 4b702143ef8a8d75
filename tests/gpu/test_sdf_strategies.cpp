// The scene-to-shader strategies (sdf/glsl_codegen.hpp) draw the same image, and the renderer's
// program cache: a parameter edit under the buffer strategy compiles nothing, a structural
// edit compiles once.
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include "render/readback.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/compiler.hpp"

#include <algorithm>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// Colour within 2/255 on all but `colourFraction` of pixels (0.2%); the id AOVs equal on all
// but 0.5% (a silhouette pixel may flip where the last bits of a distance differ).
void expectSameImages(const PreparedScene& prepared, SdfStrategy a, SdfStrategy b,
                      const std::string& name, double colourFraction = 0.002) {
    const int width = 160, height = 96;
    const FrameTargets first = renderPrepared(prepared, width, height, nullptr, a);
    const FrameTargets second = renderPrepared(prepared, width, height, nullptr, b);
    EXPECT_TRUE(
        imagesMatch(readDisplayColor(second), readDisplayColor(first), name, {2, colourFraction}));
    const Pixels<std::uint32_t> idsA = readObjectIds(first);
    const Pixels<std::uint32_t> idsB = readObjectIds(second);
    int differing = 0;
    int sdfPixels = 0;
    for (std::size_t i = 0; i < idsA.data.size(); ++i) {
        differing += idsA.data[i] != idsB.data[i];
        sdfPixels += idsA.data[i] >= kSdfIdBase;
    }
    EXPECT_GT(sdfPixels, int(idsA.data.size() / 10)) << "the scene should show SDF objects";
    EXPECT_LE(differing, int(idsA.data.size() / 200));
}

} // namespace

// Every modifier, profile and operation of the samples through generated code, parameters as
// literals and read from the buffer.
TEST(SdfStrategies, BakedAndBufferDrawTheSameImage) {
    for (const char* name : {"modifiers", "csg", "smooth_blend", "materials"}) {
        SCOPED_TRACE(name);
        const PreparedScene prepared =
            openRepositoryScene(std::string("samples/scenes/") + name + ".json");
        expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Buffer,
                         std::string("strategy_buffer_") + name);
    }
}

// The generic interpreter against generated code (one scene: the interpreter takes tens of
// seconds to compile on llvmpipe).
TEST(SdfStrategies, InterpreterAndBakedDrawTheSameImage) {
    const PreparedScene prepared = openRepositoryScene("samples/scenes/csg.json");
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Interpreter,
                     "strategy_interpreter_csg");
}

// A program of box tests and one-shape parts runs through the lean interpreter
// (common/sdf_parts_loop.glsl), which must draw what generated code draws.
TEST(SdfStrategies, PartsLoopAndBakedDrawTheSameImage) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/grid_10.json");
    ASSERT_NE(generateSdfMap(prepared.sdf, SdfStrategy::Interpreter).find("sdf_parts_loop.glsl"),
              std::string::npos);
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Interpreter,
                     "strategy_parts_loop_grid_10");
}

// A union of shapes drawn with cells runs the lean loop over lists of shapes alone, and takes
// the normal at a hit from the nearest shape's field (common/sdf_cells.glsl): it must draw what
// generated code draws, normals and shading included.
TEST(SdfStrategies, CellsOfAUnionOfShapesAndBakedDrawTheSameImage) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/grid_10.json");
    ASSERT_NE(generateSdfMap(prepared.sdf, SdfStrategy::Cells).find("SDF_CELLS_LEAN"),
              std::string::npos);
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells, "strategy_cells_grid_10");
    // Profiles (their leaves read the data buffer) and a floor plane (its cells affine, crossed
    // in a step) among the shapes.
    const PreparedScene profiles = prepareSceneText(R"({"version": 1,
        "camera": {"position": [0.5, 2.2, 5.5], "target": [0, 0.4, 0], "fov": 40},
        "materials": {"a": {"base_color": "#e76f51"}, "b": {"base_color": "#2a9d8f"}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"children": [
          {"shape": "plane", "normal": [0, 1, 0], "offset": 0, "material": "b"},
          {"shape": "revolution", "offset": 0.0, "position": [-1, 0, 0], "material": "a",
           "profile": {"type": "polygon", "points": [[0.0, 0.0], [0.4, 0.0], [0.2, 0.5],
                                                     [0.3, 0.9], [0.0, 0.9]]}},
          {"shape": "extrusion", "depth": 0.2, "position": [0.6, 0.6, 0], "material": "b",
           "profile": {"type": "polygon", "points": [[0.0, 0.45], [0.11, 0.15], [0.43, 0.14],
                                                     [0.17, -0.05], [0.26, -0.36], [0.0, -0.18],
                                                     [-0.26, -0.36], [-0.17, -0.05], [-0.43, 0.14],
                                                     [-0.11, 0.15]]}},
          {"shape": "sphere", "radius": 0.3, "position": [1.6, 0.3, -0.4], "material": "a"},
          {"shape": "box", "half_extents": [0.25, 0.25, 0.25], "position": [0, 0.25, 1],
           "rotation": [0, 30, 0], "material": "a"}]}})");
    ASSERT_NE(generateSdfMap(profiles.sdf, SdfStrategy::Cells).find("SDF_CELLS_LEAN"),
              std::string::npos);
    expectSameImages(profiles, SdfStrategy::Baked, SdfStrategy::Cells,
                     "strategy_cells_profiles_on_a_floor");
}

// A smooth-CSG tree drawn with cells runs the interpreter on each cell's postfix list, and
// reads the surface at a hit from the list of the hit's cell (common/sdf_interpreter.glsl):
// colours blended by smooth operations across three materials, a subtraction's and an
// intersection's sides, a chamfer and a distance modifier; it must draw what generated code
// draws. (The grids' lean loop has its own test above.)
TEST(SdfStrategies, CellsOfASmoothTreeAndBakedDrawTheSameImage) {
    // The smooth operations' curves (sdf/glsl_codegen.cpp passes the one curve a program uses as
    // a constant): the polynomial alone, the circular arc alone, and both.
    struct Curves {
        const char* outer;
        const char* inner;
        const char* subtraction;
        const char* constant; // in the map's combine dispatch, or none where both are used
    };
    for (const Curves& curves :
         {Curves{"polynomial", "polynomial", "polynomial", "vec4(opParams.x, 0.0, opParams.zw)"},
          Curves{"circular", "circular", "circular", "vec4(opParams.x, 1.0, opParams.zw)"},
          Curves{"circular", "polynomial", "circular", nullptr}}) {
        SCOPED_TRACE(std::string(curves.outer) + " " + curves.inner);
        const auto blend = [](const char* curve) {
            return std::string(R"("blend": ")") + curve + "\", ";
        };
        const PreparedScene prepared = prepareSceneText(R"({"version": 1,
        "camera": {"position": [0.4, 1.6, 4.2], "target": [0, 0.4, 0], "fov": 45},
        "materials": {"a": {"base_color": "#e76f51", "roughness": 0.3},
                      "b": {"base_color": "#2a9d8f", "metallic": 0.6},
                      "c": {"base_color": "#e9c46a", "emissive": [0.2, 0.1, 0.0]}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"children": [
          {"shape": "plane", "normal": [0, 1, 0], "offset": 0, "material": "b"},
          {"op": "smooth_union", )" + blend(curves.outer) +
                                                        R"("smoothness": 0.35, "children": [
            {"shape": "sphere", "radius": 0.45, "position": [-0.8, 0.45, 0], "material": "a"},
            {"op": "smooth_union", )" + blend(curves.inner) +
                                                        R"("smoothness": 0.25, "children": [
              {"shape": "sphere", "radius": 0.4, "position": [-0.2, 0.6, 0.1], "material": "c"},
              {"shape": "box", "half_extents": [0.3, 0.2, 0.3], "position": [-0.5, 0.2, 0.5],
               "material": "b", "modifiers": [{"type": "round", "radius": 0.05}]}]}]},
          {"op": "smooth_subtraction", )" + blend(curves.subtraction) +
                                                        R"("smoothness": 0.1, "children": [
            {"shape": "box", "half_extents": [0.35, 0.35, 0.35], "position": [0.7, 0.35, 0],
             "material": "c"},
            {"shape": "sphere", "radius": 0.3, "position": [0.7, 0.6, 0.3], "material": "a"}]},
          {"op": "intersection", "children": [
            {"shape": "sphere", "radius": 0.4, "position": [1.5, 0.4, -0.4], "material": "a"},
            {"shape": "box", "half_extents": [0.3, 0.3, 0.3], "position": [1.5, 0.4, -0.4],
             "material": "b"}]},
          {"op": "chamfer_union", "smoothness": 0.15, "children": [
            {"shape": "sphere", "radius": 0.3, "position": [0.1, 0.3, -0.9], "material": "b"},
            {"shape": "sphere", "radius": 0.3, "position": [0.5, 0.3, -0.9], "material": "c"}]}
        ]}})");
        const std::string map = generateSdfMap(prepared.sdf, SdfStrategy::Cells);
        ASSERT_NE(map.find("common/sdf_cells.glsl"), std::string::npos); // cells, not a fallback
        ASSERT_EQ(map.find("SDF_CELLS_LEAN"), std::string::npos);
        EXPECT_EQ(map.find("opParams.zw") != std::string::npos, curves.constant != nullptr);
        if (curves.constant) {
            EXPECT_NE(map.find(curves.constant), std::string::npos) << map;
        }
        expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells,
                         std::string("strategy_cells_smooth_tree_") + curves.outer + "_" +
                             curves.inner);
    }
}

// A grid whose lists are all short is read one list instruction per loop iteration, and one
// whose lists' stacks are all shallow holds the stacks in variables (sdf/glsl_codegen.hpp,
// SdfCellFit): the 256-sphere tree fits both, and draws what the text for any grid (two per
// iteration, arrays) draws: the same instructions in the same order, so the same pixels. A grid
// with a long list gets the second loop (the first would spend llvmpipe's loop budget: the
// 1,000-node test of test_sdf_hierarchy.cpp loses ids with it).
TEST(SdfStrategies, CellsOfShortListsDrawTheSameWithEitherLoop) {
    Renderer& renderer = sharedRenderer(); // (and the context)
    const PreparedScene prepared = openRepositoryScene("samples/bench/tree_256.json");
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells);
    ASSERT_NE(gpu.sdfMap.find("common/sdf_cells.glsl"), std::string::npos);
    ASSERT_EQ(gpu.sdfMap.find("SDF_CELLS_LEAN"), std::string::npos); // the postfix loop
    EXPECT_NE(gpu.sdfMap.find("SDF_CELLS_SHORT_LISTS"), std::string::npos);
    EXPECT_NE(gpu.sdfMap.find("SDF_CELLS_SHALLOW_STACKS"), std::string::npos);
    EXPECT_EQ(gpu.sdfCellStats.maxStack, 4); // (three entries below the top: the variables')
    const int width = 160, height = 96;
    FrameTargets one = createFrameTargets(width, height);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, one);
    for (const SdfCellFit fit : {SdfCellFit{.shortLists = true}, SdfCellFit{}}) {
        gpu.sdfMap = generateSdfMap(prepared.sdf, SdfStrategy::Cells, {}, {}, fit);
        ASSERT_EQ(gpu.sdfMap.find("SDF_CELLS_SHALLOW_STACKS"), std::string::npos);
        ASSERT_EQ(gpu.sdfMap.find("SDF_CELLS_SHORT_LISTS") != std::string::npos, fit.shortLists);
        FrameTargets two = createFrameTargets(width, height);
        renderer.render(gpu, prepared.scene.camera, prepared.scene.render, two);
        expectNoGlErrors();
        EXPECT_TRUE(imagesMatch(readDisplayColor(two), readDisplayColor(one),
                                fit.shortLists ? "strategy_cells_shallow_stacks"
                                               : "strategy_cells_short_lists",
                                {0, 0.0}));
        EXPECT_EQ(readObjectIds(two).data, readObjectIds(one).data);
    }

    std::string spheres;
    for (int i = 0; i < 80; ++i)
        spheres += std::string(i ? ", " : "") + R"({"shape": "sphere", "radius": 0.3,
            "position": [)" +
                   std::to_string(0.001 * i) + ", 0.3, 0]}";
    const PreparedScene overlapping = prepareSceneText(
        R"({"version": 1, "sdf": {"op": "smooth_union", "smoothness": 0.1, "children": [)" +
        spheres + "]}}");
    const GpuScene long_ = uploadScene(overlapping, SdfStrategy::Cells);
    ASSERT_NE(long_.sdfMap.find("common/sdf_cells.glsl"), std::string::npos);
    EXPECT_GT(long_.sdfCellStats.maxLength, kSdfShortCellList);
    EXPECT_EQ(long_.sdfMap.find("SDF_CELLS_SHORT_LISTS"), std::string::npos);
}

// A grid with a list deeper than the stack variables hold (seven spheres nested to the right,
// op(s0, op(s1, ... s6)): seven leaves before the first combine) keeps its stacks in arrays, and
// must: drawn with the variables it loses the entries they do not hold (the fifth and sixth
// spheres, here the largest), and the picture changes.
TEST(SdfStrategies, CellsOfDeepListsKeepTheirStacksInArrays) {
    Renderer& renderer = sharedRenderer();
    std::string nested;
    for (int i = 6; i >= 0; --i) {
        const bool large = i == 4 || i == 5;
        const std::string sphere = std::string(R"({"shape": "sphere", "radius": )") +
                                   (large ? "0.5" : "0.3") + R"(, "position": [)" +
                                   std::to_string(0.02 * i) + R"(, 0, 0], "material": ")" +
                                   (large ? "a" : "b") + "\"}";
        nested = i == 6 ? sphere
                        : R"({"op": "smooth_union", "smoothness": 0.3, "children": [)" + sphere +
                              ", " + nested + "]}";
    }
    const PreparedScene prepared = prepareSceneText(R"({"version": 1,
        "camera": {"position": [0, 0.4, 1.8], "target": [0.06, 0, 0], "fov": 50},
        "materials": {"a": {"base_color": "#e76f51"}, "b": {"base_color": "#2a9d8f"}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": )" + nested + "}");
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells);
    ASSERT_NE(gpu.sdfMap.find("common/sdf_cells.glsl"), std::string::npos);
    EXPECT_EQ(gpu.sdfCellStats.maxStack, 7);
    EXPECT_EQ(gpu.sdfMap.find("SDF_CELLS_SHALLOW_STACKS"), std::string::npos);
    const int width = 96, height = 64;
    FrameTargets arrays = createFrameTargets(width, height);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, arrays);
    gpu.sdfMap = generateSdfMap(prepared.sdf, SdfStrategy::Cells, {}, {},
                                SdfCellFit{.shortLists = true, .shallowStacks = true});
    FrameTargets variables = createFrameTargets(width, height);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, variables);
    expectNoGlErrors();
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells, "strategy_cells_deep_lists");
    const Pixels<std::uint8_t> a = readDisplayColor(arrays), v = readDisplayColor(variables);
    int differing = 0;
    for (std::size_t k = 0; k < a.data.size(); k += 4)
        differing += std::abs(int(a.data[k]) - int(v.data[k])) > 8 ||
                     std::abs(int(a.data[k + 1]) - int(v.data[k + 1])) > 8 ||
                     std::abs(int(a.data[k + 2]) - int(v.data[k + 2])) > 8;
    EXPECT_GT(differing, width * height / 5); // (measured: 1,486 of 6,144 pixels)
}

// A room: a floor and two walls are the grid's planes, in no list (engine/sdf/cell_pruning.hpp,
// SdfCellGrid::planes): each point unites its list with them, the surface at a hit takes the
// nearest plane's material and id, and a cell whose program was one of them is crossed to it by
// the nearest plane's slope. With smooth unions (postfix lists) and a plain union of shapes (the
// lean loop), it must draw what generated code draws. (The lean loop's walls stand behind the
// camera: where two planes meet in a concave seam, its normal is the nearest shape's gradient,
// generated code's the union's, which bends within a tap of the seam; so it drew before the
// planes left the lists too.)
TEST(SdfStrategies, CellsOfARoomOfPlanesAndBakedDrawTheSameImage) {
    for (const bool smooth : {true, false}) {
        const std::string op = smooth ? "smooth_union" : "union";
        const std::string walls = smooth ? R"(
              {"shape": "plane", "normal": [0.2, 0, 1], "offset": -1.5, "material": "c"},
              {"shape": "plane", "normal": [1, 0, -0.1], "offset": -1.8, "position": [0, 0.2, 0],
               "rotation": [0, 10, 5], "material": "a"},)"
                                         : R"(
              {"shape": "plane", "normal": [0, 0, -1], "offset": -5, "material": "c"},
              {"shape": "plane", "normal": [-1, 0.1, 0], "offset": -6, "position": [0, 0.2, 0],
               "rotation": [0, 10, 5], "material": "a"},)";
        const PreparedScene prepared = prepareSceneText(R"({"version": 1,
            "camera": {"position": [1.2, 1.0, 3.5], "target": [-0.3, 0.5, 0], "fov": 55},
            "materials": {"a": {"base_color": "#e76f51", "roughness": 0.3},
                          "b": {"base_color": "#2a9d8f", "metallic": 0.6},
                          "c": {"base_color": "#e9c46a", "emissive": [0.2, 0.1, 0.0]}},
            "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
            "sdf": {"children": [
              {"shape": "plane", "normal": [0, 1, 0], "offset": 0, "material": "b"},)" +
                                                        walls +
                                                        R"(
              {"op": ")" + op + R"(", "smoothness": 0.2, "children": [
                {"shape": "sphere", "radius": 0.4, "position": [-0.6, 0.4, 0], "material": "a"},
                {"shape": "box", "half_extents": [0.3, 0.3, 0.3], "position": [0.1, 0.3, 0.2],
                 "material": "c"}]}
            ]}})");
        const std::string map = generateSdfMap(prepared.sdf, SdfStrategy::Cells);
        ASSERT_NE(map.find("common/sdf_cells.glsl"), std::string::npos);
        EXPECT_EQ(map.find("SDF_CELLS_LEAN") == std::string::npos, smooth);
        const SdfCellGrid grid = buildSdfCells(prepared.sdf, sdfContentBox(*prepared.scene.sdf));
        ASSERT_GT(grid.levels, 0);
        EXPECT_EQ(grid.planes.size(), 3u);
        EXPECT_NE(map.find("#define SDF_CELLS_PLANES 3\n"), std::string::npos); // (all read)
        // (Rays that come down to the content's box or land on a wall in a step, common/
        // sdf_cells.glsl sdfDistanceAlong, meet the seams of two planes at other points within
        // the hit threshold than generated code's march: 45 pixels of the smooth room differ
        // by more than 2/255, each faintly; the march with a hundredth of the threshold differs
        // from each of the two images at as many pixels, 115 and 114.)
        expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells,
                         smooth ? "strategy_cells_room_smooth" : "strategy_cells_room",
                         smooth ? 0.003 : 0.002);
    }
}

// Seen from outside the cells' grid, a scene drawn with cells runs the outside list (the floor
// plane) with the distance to the content's floor box standing for the rest, and no bounding
// hierarchy (common/sdf_cells.glsl, sdfCellDistance): rays march towards the content by that
// box, and the plane reaches the horizon outside the grid. It must draw what generated code
// draws.
TEST(SdfStrategies, CellsSeenFromOutsideTheGridAndBakedDrawTheSameImage) {
    const PreparedScene prepared = prepareSceneText(R"({"version": 1,
        "camera": {"position": [6, 4, 40], "target": [0.3, 0.3, 0], "fov": 9},
        "render": {"max_distance": 120},
        "materials": {"a": {"base_color": "#e76f51", "roughness": 0.3},
                      "b": {"base_color": "#2a9d8f", "metallic": 0.6},
                      "c": {"base_color": "#e9c46a"}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"children": [
          {"shape": "plane", "normal": [0, 1, 0], "offset": 0, "material": "b"},
          {"op": "smooth_union", "smoothness": 0.3, "children": [
            {"shape": "sphere", "radius": 0.45, "position": [-0.6, 0.45, 0], "material": "a"},
            {"shape": "sphere", "radius": 0.4, "position": [0.0, 0.6, 0.1], "material": "c"}]},
          {"op": "subtraction", "children": [
            {"shape": "box", "half_extents": [0.35, 0.35, 0.35], "position": [0.9, 0.35, 0],
             "material": "c"},
            {"shape": "sphere", "radius": 0.3, "position": [0.9, 0.6, 0.3], "material": "a"}]},
          {"shape": "torus", "major_radius": 0.3, "minor_radius": 0.1, "position": [0.2, 0.1, -0.8], "material": "a"}
        ]}})");
    const std::string map = generateSdfMap(prepared.sdf, SdfStrategy::Cells);
    ASSERT_NE(map.find("common/sdf_cells.glsl"), std::string::npos);
    ASSERT_NE(map.find("#define SDF_HAS_BOUNDS 0"), std::string::npos) << map;
    const SdfCellGrid grid = buildSdfCells(prepared.sdf, sdfContentBox(*prepared.scene.sdf));
    ASSERT_GT(grid.levels, 0);
    ASSERT_TRUE(grid.outsideFloor);
    EXPECT_EQ(grid.outsideLength, 0u); // the plane is the grid's, in no list
    EXPECT_EQ(grid.planes.size(), 1u);
    const glm::vec3 camera = prepared.scene.camera.position;
    EXPECT_TRUE(glm::any(glm::lessThan(camera, grid.origin)) ||
                glm::any(glm::greaterThan(camera, grid.origin + glm::vec3(grid.size))))
        << "the camera should be outside the grid";
    // (The rays come down to the content's box in a step, common/sdf_cells.glsl
    // sdfDistanceAlong, and so sample the last of their march elsewhere than generated code's,
    // where objects meet the floor within the hit threshold (0.04 at this distance): 52 pixels
    // differ by more than 2/255. The march with a hundredth of the threshold differs from
    // generated code's image at 458 pixels, from the cells' at 465, from the cells' before the
    // step at 455.)
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells,
                     "strategy_cells_from_outside", 0.0035);
}

// A ray that meets the content (everything but the grid's planes) nowhere for a while goes to
// the box that bounds it, or to the first plane it lands on, in one step (common/sdf_cells.glsl,
// sdfContentEntry): over the 256-sphere tree on its floor the march takes 5.4 steps a marched
// pixel, where crossing the empty cells above the spheres one a step took 12.5; and rays past
// the spheres land on the floor in two.
TEST(SdfStrategies, CellsComeDownToTheContentInAStep) {
    Renderer& renderer = sharedRenderer(); // (and the context)
    const PreparedScene prepared = openRepositoryScene("samples/bench/tree_256.json");
    const GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells);
    ASSERT_NE(gpu.sdfMap.find("common/sdf_cells.glsl"), std::string::npos);
    FrameTargets targets = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, targets);
    const Pixels<float> steps = readMarchSteps(targets);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    const std::uint32_t floorId = kSdfIdBase + 1;   // the root's first child
    std::size_t firstSphereRow = steps.data.size(); // (rows from the top)
    for (std::size_t i = 0; i < ids.data.size(); ++i)
        if (ids.data[i] > floorId) firstSphereRow = std::min(firstSphereRow, i / ids.width);
    double marched = 0.0, total = 0.0;
    int floorFar = 0, floorFarSteps = 0;
    for (std::size_t i = 0; i < steps.data.size(); ++i) {
        if (steps.data[i] == 0.0f) continue;
        marched += 1.0;
        total += steps.data[i];
        // The floor beyond the spheres: the rows above the field's first.
        if (ids.data[i] == floorId && i / steps.width < firstSphereRow) {
            ++floorFar;
            floorFarSteps = std::max(floorFarSteps, int(steps.data[i]));
        }
    }
    ASSERT_GT(marched, 0.5 * double(steps.data.size()));
    EXPECT_LT(total / marched, 5.5); // 5.38
    EXPECT_GT(floorFar, 2000);       // 2,240
    EXPECT_LE(floorFarSteps, 2);
}

// Twisted shapes have no floor (a twist's field is no distance to a box), so nothing told the
// march where the content ends: a ray that passed between them crossed the grid's empty space to
// its far side, the content's cube grown 16 times. It now ends where it leaves the scene's bounds
// at a level above the hit threshold (sdfHitEnd, common/sdf_cells.glsl; the header's hit-end
// box, render/gpu_scene.cpp), where no hit can lie: exactly the picture, the depths and the ids
// the march drew without that end, in a fraction of the steps.
TEST(SdfStrategies, CellsEndRaysWhereTheyLeaveTheContentsBounds) {
    std::ostringstream sdf;
    sdf << R"({"version": 1, "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov": 40},
        "materials": {"a": {"base_color": "#e76f51"}, "b": {"base_color": "#2a9d8f"}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"children": [)";
    for (int i = 0; i < 24; ++i)
        sdf << (i ? ", " : "") << R"({"rotation": [0, )" << (i * 37) % 80 - 40
            << R"(, 0], "position": [)" << (i % 6) * 0.6f - 1.5f << ", " << (i / 6) * 0.6f - 0.9f
            << R"(, 0], "children": [{"shape": "capsule", "half_height": 0.15, "radius": 0.08,
                "material": ")"
            << (i % 2 ? "a" : "b") << R"(", "modifiers": [{"type": "twist",
                "amount": 60, "radius": 0.1}]}, {"shape": "box", "half_extents": [0.1, 0.1, 0.1],
                "position": [0.15, 0.15, 0]}]})";
    sdf << "]}}";
    const PreparedScene prepared = prepareSceneText(sdf.str());
    Renderer& renderer = sharedRenderer(); // (and the context)
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells);
    ASSERT_NE(gpu.sdfMap.find("common/sdf_cells.glsl"), std::string::npos);
    ASSERT_GT(gpu.sdfCellHeader.hitEndMin.w, 0.0f);
    FrameTargets targets = createFrameTargets(160, 96);
    const auto draw = [&](Pixels<float>& steps, Pixels<float>& depths, Pixels<std::uint32_t>& ids) {
        renderer.render(gpu, prepared.scene.camera, prepared.scene.render, targets);
        steps = readMarchSteps(targets);
        depths = readViewDepth(targets);
        ids = readObjectIds(targets);
        return readDisplayColor(targets);
    };
    Pixels<float> steps, depths, endlessSteps, endlessDepths;
    Pixels<std::uint32_t> ids, endlessIds;
    const auto colour = draw(steps, depths, ids);
    gpu.sdfCellHeader.hitEndMin.w = 0.0f; // no hit end: the rays cross the grid
    glNamedBufferSubData(gpu.sdfCells.id(), 0, sizeof gpu.sdfCellHeader, &gpu.sdfCellHeader);
    const auto endless = draw(endlessSteps, endlessDepths, endlessIds);
    EXPECT_TRUE(imagesMatch(colour, endless, "strategy_cells_hit_end", {0, 0.0}));
    EXPECT_EQ(depths.data, endlessDepths.data);
    EXPECT_EQ(ids.data, endlessIds.data);
    double missed = 0.0, missedSteps = 0.0, endlessMissedSteps = 0.0;
    for (std::size_t i = 0; i < steps.data.size(); ++i)
        if (steps.data[i] > 0.0f && ids.data[i] == 0u) {
            missed += 1.0;
            missedSteps += steps.data[i];
            endlessMissedSteps += endlessSteps.data[i];
        }
    ASSERT_GT(missed, 7000.0);                        // the rays between the shapes: 7,449
    EXPECT_LT(missedSteps / missed, 6.0);             // 5.67
    EXPECT_LT(missedSteps, 0.5 * endlessMissedSteps); // 14.06 a missed pixel without
}

// A ray level with the floor, or rising slightly, still meets it: the hit threshold grows by
// epsilon a unit of distance and catches up with a field that grows more slowly (the march
// stops there). Looking away from the content, every ray misses its box, and the step to the
// first plane it lands on must count such a plane (sdfPlaneLanding, common/sdf_cells.glsl):
// with a large threshold the band where that happens is rows of pixels at the horizon.
TEST(SdfStrategies, CellsLandOnAFloorLevelWithTheRay) {
    const PreparedScene prepared = prepareSceneText(R"({"version": 1,
        "camera": {"position": [0, 0.2, 10], "target": [0, 0.2, 20], "fov": 45},
        "render": {"surface_epsilon": 0.01, "max_distance": 100},
        "materials": {"a": {"base_color": "#e76f51"}, "b": {"base_color": "#2a9d8f"}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, 1.0], "intensity": 3.0}],
        "sdf": {"children": [
          {"shape": "plane", "normal": [0, 1, 0], "offset": 0, "material": "b"},
          {"shape": "box", "half_extents": [4, 4, 4], "position": [0, 4, 0], "material": "a"}
        ]}})");
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells, "strategy_cells_level");
    // A flat floor under a directional light has one colour near and far: the depths tell.
    const int width = 160, height = 96;
    const Pixels<float> baked =
        readViewDepth(renderPrepared(prepared, width, height, nullptr, SdfStrategy::Baked));
    const Pixels<float> cells =
        readViewDepth(renderPrepared(prepared, width, height, nullptr, SdfStrategy::Cells));
    int far = 0, differing = 0;
    for (std::size_t i = 0; i < baked.data.size(); ++i) {
        const float a = baked.data[i], b = cells.data[i];
        far += a != kNoDepth && a > 15.0f && a < 90.0f; // the threshold caught up: at 20 or so
        differing +=
            (a == kNoDepth) != (b == kNoDepth) || (a != kNoDepth && std::abs(a - b) > 0.02f * a);
    }
    EXPECT_GE(far, width); // (a row of pixels at this size)
    EXPECT_EQ(differing, 0);
}

// Every point and distance modifier of the samples drawn with cells runs the interpreter's
// surface read, which also carries the normal's four taps through the modifiers and frames
// (sdfSurfaceRead, common/sdf_interpreter.glsl): it must draw what generated code draws. Without
// the scene's soft shadows and AO: in far cells they read the cells' constants, which are below
// the distance, so the penumbrae differ (README, "How a frame is made").
TEST(SdfStrategies, CellsOfModifiedShapesAndBakedDrawTheSameImage) {
    PreparedScene prepared = openRepositoryScene("samples/scenes/modifiers.json");
    prepared.scene.render.shadows.enabled = false;
    prepared.scene.render.ao.samples = 0;
    const std::string map = generateSdfMap(prepared.sdf, SdfStrategy::Cells);
    ASSERT_NE(map.find("common/sdf_cells.glsl"), std::string::npos);
    ASSERT_NE(map.find("#define SDF_HAS_POINT_MODIFIERS 1"), std::string::npos) << map;
    ASSERT_NE(map.find("#define SDF_HAS_DISTANCE_MODIFIERS 1"), std::string::npos) << map;
    ASSERT_NE(map.find("#define SDF_HAS_POINT_FRAMES 1"), std::string::npos) << map;
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Cells, "strategy_cells_modifiers");

    // Its frames' points are pushed: held in variables (SdfCellFit::shallowStacks), they draw
    // exactly what the arrays of the map for any grid draw.
    Renderer& renderer = sharedRenderer();
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells);
    EXPECT_EQ(gpu.sdfCellStats.maxPointStack, 1);
    const SdfCellFit fit = sdfMapCellFit(gpu.sdfMap);
    EXPECT_TRUE(fit.shallowStacks);
    FrameTargets variables = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, variables);
    gpu.sdfMap =
        generateSdfMap(prepared.sdf, SdfStrategy::Cells, {}, {}, {.shortLists = fit.shortLists});
    FrameTargets arrays = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, arrays);
    expectNoGlErrors();
    EXPECT_TRUE(imagesMatch(readDisplayColor(variables), readDisplayColor(arrays),
                            "strategy_cells_modifiers_shallow_stacks", {0, 0.0}));
    EXPECT_EQ(readObjectIds(variables).data, readObjectIds(arrays).data);
}

TEST(SdfStrategies, ParameterEditsReuseTheProgramStructuralEditsCompile) {
    PreparedScene prepared = openRepositoryScene("samples/scenes/csg.json");
    Renderer& renderer = sharedRenderer();
    std::string error;
    const GpuScene before = uploadScene(prepared, SdfStrategy::Buffer);
    ASSERT_TRUE(renderer.prepare(before, error)) << error;

    // A parameter edit: the first shape's parameters and transform change, nothing else.
    ASSERT_FALSE(prepared.sdf.instructions.empty());
    for (GpuSdfInstruction& in : prepared.sdf.instructions) {
        if (SdfOpcode(in.opcode) != SdfOpcode::Shape) continue;
        in.params[0].x *= 1.1f;
        in.worldToLocal[0].w += 0.05f;
        break;
    }
    const GpuScene edited = uploadScene(prepared, SdfStrategy::Buffer);
    EXPECT_EQ(edited.sdfMap, before.sdfMap);
    ASSERT_TRUE(renderer.prepare(edited, error)) << error;
    EXPECT_EQ(renderer.lastCompileMs(), 0.0) << "a parameter edit must not compile shaders";

    // Baked, the same edit is new code.
    EXPECT_NE(
        uploadScene(prepared, SdfStrategy::Baked).sdfMap,
        uploadScene(openRepositoryScene("samples/scenes/csg.json"), SdfStrategy::Baked).sdfMap);

    // A structural edit (an operation changes) compiles once, then is cached.
    for (GpuSdfInstruction& in : prepared.sdf.instructions) {
        if (SdfOpcode(in.opcode) != SdfOpcode::Combine) continue;
        in.kind = in.kind == std::uint32_t(SdfOp::Union) ? std::uint32_t(SdfOp::Intersection)
                                                         : std::uint32_t(SdfOp::Union);
        break;
    }
    const GpuScene restructured = uploadScene(prepared, SdfStrategy::Buffer);
    EXPECT_NE(restructured.sdfMap, before.sdfMap);
    ASSERT_TRUE(renderer.prepare(restructured, error)) << error;
    EXPECT_GT(renderer.lastCompileMs(), 0.0);
    RecordProperty("structural_edit_compile_ms", std::to_string(renderer.lastCompileMs()));
    ASSERT_TRUE(renderer.prepare(restructured, error)) << error;
    EXPECT_EQ(renderer.lastCompileMs(), 0.0);
    expectNoGlErrors();
}

// The interpreter's surface read (common/sdf_interpreter.glsl, sdfSurfaceRead) through a
// bounding hierarchy whose parts are groups blended by smooth, chamfer and round unions, not
// single shapes (so not the parts loop): each part's surface is united into the running best by
// Accumulate. Generated code draws the same program with the same hierarchy.
TEST(SdfStrategies, TheInterpreterReadsSurfacesThroughAHierarchyOfGroups) {
    const PreparedScene prepared = prepareSceneText(R"({"version": 1,
        "camera": {"position": [0.0, 1.5, 3.0], "target": [0, 0.3, 0.3], "fov": 60},
        "materials": {"a": {"base_color": "#e76f51", "roughness": 0.3},
                      "b": {"base_color": "#2a9d8f", "metallic": 0.6},
                      "c": {"base_color": "#e9c46a", "emissive": [0.2, 0.1, 0.0]}},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"children": [
          {"op": "smooth_union", "smoothness": 0.2, "children": [
            {"shape": "sphere", "radius": 0.4, "position": [-1.6, 0.4, 0], "material": "a"},
            {"shape": "box", "half_extents": [0.3, 0.2, 0.3], "position": [-1.2, 0.2, 0.3],
             "material": "b"}]},
          {"op": "chamfer_union", "smoothness": 0.1, "children": [
            {"shape": "box", "half_extents": [0.3, 0.3, 0.3], "position": [-0.4, 0.3, 0],
             "material": "c"},
            {"shape": "sphere", "radius": 0.25, "position": [-0.3, 0.55, 0.2], "material": "a"}]},
          {"op": "smooth_union", "smoothness": 0.3, "children": [
            {"shape": "sphere", "radius": 0.3, "position": [0.5, 0.3, 0.2], "material": "b"},
            {"shape": "sphere", "radius": 0.25, "position": [0.8, 0.5, -0.1], "material": "c"}]},
          {"op": "round_union", "smoothness": 0.1, "children": [
            {"shape": "sphere", "radius": 0.3, "position": [1.6, 0.3, 0], "material": "a"},
            {"shape": "box", "half_extents": [0.2, 0.4, 0.2], "position": [1.9, 0.4, 0],
             "material": "b"}]},
          {"op": "smooth_union", "smoothness": 0.15, "children": [
            {"shape": "torus", "major_radius": 0.35, "minor_radius": 0.1,
             "position": [0, 0.1, 1.2], "material": "c"},
            {"shape": "sphere", "radius": 0.2, "position": [0, 0.25, 1.2], "material": "a"}]}]}})");
    ASSERT_TRUE(std::any_of(
        prepared.sdf.instructions.begin(), prepared.sdf.instructions.end(),
        [](const GpuSdfInstruction& in) { return SdfOpcode(in.opcode) == SdfOpcode::Accumulate; }))
        << "the scene should compile with a bounding hierarchy";
    ASSERT_FALSE(sdfIsLeastOfShapes(prepared.sdf)) << "its parts should be groups";
    expectSameImages(prepared, SdfStrategy::Baked, SdfStrategy::Interpreter,
                     "strategy_interpreter_hierarchy_of_groups");
}

// The compiler's bounding hierarchy skips far parts without changing the picture: with and
// without it, the 10-shape bench grid in baked code (which unites the hierarchy's parts without
// skipping) and the shapes sample (a plane, exact shapes and an ellipsoid, whose bound formula
// keeps it out of the hierarchy) through the
// interpreter.
TEST(SdfStrategies, BoundsDoNotChangeTheImage) {
    const std::pair<const char*, SdfStrategy> cases[] = {
        {"samples/bench/grid_10.json", SdfStrategy::Baked},
        {"samples/scenes/shapes.json", SdfStrategy::Interpreter}};
    for (const auto& [path, strategy] : cases) {
        SCOPED_TRACE(path);
        const PreparedScene bounded = openRepositoryScene(path);
        ASSERT_TRUE(std::any_of(bounded.sdf.instructions.begin(), bounded.sdf.instructions.end(),
                                [](const GpuSdfInstruction& in) {
                                    return SdfOpcode(in.opcode) == SdfOpcode::BoundSkip;
                                }))
            << "the scene should compile with box tests";
        PreparedScene plain = bounded;
        Diagnostics diagnostics;
        std::optional<SdfProgram> program =
            compileSdf(*plain.scene.sdf, std::uint32_t(plain.scene.materials.size()), path,
                       diagnostics, {.bounds = false});
        ASSERT_TRUE(program) << diagnostics.format();
        plain.sdf = std::move(*program);
        const int width = 160, height = 96;
        const FrameTargets a = renderPrepared(bounded, width, height, nullptr, strategy);
        const FrameTargets b = renderPrepared(plain, width, height, nullptr, strategy);
        const std::string name = std::filesystem::path(path).stem().string();
        EXPECT_TRUE(
            imagesMatch(readDisplayColor(a), readDisplayColor(b), "bounds_" + name, {2, 0.002}));
        const Pixels<std::uint32_t> idsA = readObjectIds(a), idsB = readObjectIds(b);
        int differing = 0;
        for (std::size_t i = 0; i < idsA.data.size(); ++i)
            differing += idsA.data[i] != idsB.data[i];
        EXPECT_LE(differing, int(idsA.data.size() / 200));
    }
}
