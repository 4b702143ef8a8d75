// The cells buffer after an edit (render/gpu_scene.hpp, updateSdfCells): the words a re-prune
// changed are written into the buffer in place, and the buffer then holds exactly the edited
// grid; a grid that does not fit gets a new buffer, and one deeper than the map's stack
// variables a new upload.
#include "gpu_test_support.hpp"

#include "render/gpu_scene.hpp"
#include "render/readback.hpp"
#include "scene_text.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/glsl_codegen.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// The header and words the cells buffer holds.
std::vector<std::uint32_t> readCells(const GpuScene& gpu, std::size_t words) {
    std::vector<std::uint32_t> out(sizeof(GpuSdfCellHeader) / 4 + words);
    glGetNamedBufferSubData(gpu.sdfCells.id(), 0, GLsizeiptr(out.size() * 4), out.data());
    return out;
}

std::vector<std::uint32_t> expectedCells(const GpuSdfCellHeader& header, const SdfCellGrid& grid) {
    std::vector<std::uint32_t> out(sizeof header / 4);
    std::memcpy(out.data(), &header, sizeof header);
    out.insert(out.end(), grid.words.begin(), grid.words.end());
    return out;
}

} // namespace

TEST(CellUpload, AnEditWritesOnlyWhatChangedIntoTheSameBuffer) {
    PreparedScene prepared = openRepositoryScene("samples/bench/grid_1000.json");
    sharedRenderer(); // the context
    SdfCellStatePtr state;
    SdfCellGrid grid = buildSdfCells(prepared.sdf, sdfContentBox(*prepared.scene.sdf), {}, &state);
    ASSERT_TRUE(state);
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells, &grid);
    const GLuint buffer = gpu.sdfCells.id();
    ASSERT_EQ(readCells(gpu, grid.words.size()), expectedCells(gpu.sdfCellHeader, grid));

    // Three moves of different shapes, each written over the last.
    SdfProgram edited = prepared.sdf;
    std::vector<std::size_t> shapes;
    for (std::size_t i = 0; i < edited.instructions.size(); ++i)
        if (SdfOpcode(edited.instructions[i].opcode) == SdfOpcode::Shape) shapes.push_back(i);
    ASSERT_GT(shapes.size(), 100u);
    for (std::size_t move = 0; move < 3; ++move) {
        GpuSdfInstruction& moved = edited.instructions[shapes[shapes.size() * (move + 1) / 4]];
        moved.worldToLocal[0].w += 0.3f * moved.misc.x;
        ASSERT_TRUE(repruneSdfCells(*state, edited, grid));
        std::size_t written = 0;
        for (const SdfWordRange& range : grid.changedWords)
            written += range.count;
        // A small part of the grid: 1.2% to 1.7% of its words measured on these moves.
        EXPECT_LT(written * 40, grid.words.size());
        updateSdfCells(gpu, grid);
        EXPECT_EQ(gpu.sdfCells.id(), buffer);
        EXPECT_EQ(gpu.sdfCellHeader.info.x, std::uint32_t(grid.levels));
        EXPECT_EQ(gpu.sdfCellHeader.info.y, grid.outsideOffset);
        EXPECT_TRUE(readCells(gpu, grid.words.size()) == expectedCells(gpu.sdfCellHeader, grid))
            << "move " << move;
    }

    // Two re-prunes, the first never written: the second's changes count from the first, not
    // from what the buffer holds, so it is written whole (SdfCellGrid::changedSince).
    for (std::size_t move = 0; move < 2; ++move) {
        GpuSdfInstruction& moved = edited.instructions[shapes[shapes.size() / 8 + move]];
        moved.worldToLocal[1].w += 0.4f * moved.misc.x;
        ASSERT_TRUE(repruneSdfCells(*state, edited, grid));
    }
    updateSdfCells(gpu, grid);
    EXPECT_TRUE(readCells(gpu, grid.words.size()) == expectedCells(gpu.sdfCellHeader, grid));

    // A grid larger than the buffer's room: a new buffer with all of it.
    SdfCellGrid larger = grid;
    larger.words.resize(grid.words.size() * 2, 7u);
    larger.changedWords = {{0, std::uint32_t(larger.words.size())}};
    updateSdfCells(gpu, larger);
    EXPECT_TRUE(readCells(gpu, larger.words.size()) == expectedCells(gpu.sdfCellHeader, larger));
}

// An edit of numbers drawn with the cells map, written into the uploaded scene in place
// (updateSdfScene): the same buffers, and the same picture, colour and ids, as the edited scene
// uploaded anew; a scene of another shape is refused.
TEST(CellUpload, AnEditOfNumbersIsWrittenIntoTheSceneInPlace) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/grid_1000.json");
    Renderer& renderer = sharedRenderer();
    SdfCellStatePtr state;
    SdfCellGrid grid = buildSdfCells(prepared.sdf, sdfContentBox(*prepared.scene.sdf), {}, &state);
    ASSERT_TRUE(state);
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells, &grid);
    const auto draw = [&](const GpuScene& scene, const PreparedScene& of) {
        FrameTargets targets = createFrameTargets(96, 64);
        renderer.render(scene, of.scene.camera, of.scene.render, targets);
        return std::make_pair(readDisplayColor(targets), readObjectIds(targets));
    };
    const auto before = draw(gpu, prepared);

    // Every shape moved and its material recoloured.
    PreparedScene edited = prepared;
    for (GpuSdfInstruction& in : edited.sdf.instructions)
        if (SdfOpcode(in.opcode) == SdfOpcode::Shape) in.worldToLocal[0].w += 0.25f * in.misc.x;
    ASSERT_FALSE(edited.materials.empty());
    for (Material& m : edited.materials)
        m.baseColor = glm::vec3(0.9f, 0.2f, 0.1f);
    ASSERT_TRUE(repruneSdfCells(*state, edited.sdf, grid));
    const GLuint program = gpu.sdfProgram.buffer.id(), cells = gpu.sdfCells.id();
    ASSERT_TRUE(updateSdfScene(gpu, edited, grid));
    EXPECT_EQ(gpu.sdfProgram.buffer.id(), program);
    EXPECT_EQ(gpu.sdfCells.id(), cells);
    const auto inPlace = draw(gpu, edited);
    const GpuScene fresh = uploadScene(edited, SdfStrategy::Cells, &grid);
    const auto anew = draw(fresh, edited);
    EXPECT_TRUE(inPlace.first.data == anew.first.data);
    EXPECT_TRUE(inPlace.second.data == anew.second.data);
    EXPECT_FALSE(inPlace.first.data == before.first.data); // the edit shows
    expectNoGlErrors();

    // The scene's first part moved far out of the grid's cube (its tree, which the flag is read
    // from; the program and cells are kept): the header no longer says every surface is inside,
    // as a new upload would not, so rays go on past the grid.
    PreparedScene outside = edited;
    ASSERT_TRUE(outside.scene.sdf && !outside.scene.sdf->children.empty());
    outside.scene.sdf->children.front().transform.position.x += 4.0f * grid.size;
    ASSERT_EQ(gpu.sdfCellHeader.info.w, 1u);
    ASSERT_TRUE(updateSdfScene(gpu, outside, grid));
    const GpuScene freshOutside = uploadScene(outside, SdfStrategy::Cells, &grid);
    EXPECT_EQ(freshOutside.sdfCellHeader.info.w, 0u);
    GpuSdfCellHeader written;
    glGetNamedBufferSubData(gpu.sdfCells.id(), 0, sizeof written, &written);
    EXPECT_EQ(written.info.w, freshOutside.sdfCellHeader.info.w);

    PreparedScene longer = edited;
    longer.sdf.instructions.push_back(longer.sdf.instructions.front());
    EXPECT_FALSE(updateSdfScene(gpu, longer, grid));
}

// A map that holds its stacks in variables (sdf/glsl_codegen.hpp, SdfCellFit) is not given a
// grid whose lists an edit made deeper than they hold: seven spheres nested to the right,
// op(s0, op(s1, ... s6)), apart (each cell lists one or two) and then moved together (the cells
// there list all seven, seven leaves before the first combine). updateSdfScene refuses; a new
// upload gets the map for any grid.
TEST(CellUpload, AnEditThatDeepensTheListsIsNotWrittenIntoShallowStacks) {
    sharedRenderer(); // (the context the uploads need)
    std::string nested;
    for (int i = 6; i >= 0; --i) {
        const std::string sphere =
            R"({"shape": "sphere", "radius": 0.3, "position": [)" + std::to_string(i) + ", 0, 0]}";
        nested = i == 6 ? sphere
                        : R"({"op": "smooth_union", "smoothness": 0.3, "children": [)" + sphere +
                              ", " + nested + "]}";
    }
    const PreparedScene apart = prepareSceneText(R"({"version": 1, "sdf": )" + nested + "}");
    SdfCellStatePtr state;
    SdfCellGrid grid = buildSdfCells(apart.sdf, sdfContentBox(*apart.scene.sdf), {}, &state);
    ASSERT_TRUE(state);
    EXPECT_EQ(sdfDeepestCellStack(grid), 4); // (within kSdfRegisterStack)
    GpuScene gpu = uploadScene(apart, SdfStrategy::Cells, &grid);
    ASSERT_TRUE(sdfMapCellFit(gpu.sdfMap).shallowStacks);

    PreparedScene together = apart;
    for (GpuSdfInstruction& in : together.sdf.instructions)
        if (SdfOpcode(in.opcode) == SdfOpcode::Shape) in.worldToLocal[0].w = -3.0f;
    ASSERT_TRUE(repruneSdfCells(*state, together.sdf, grid));
    EXPECT_EQ(sdfDeepestCellStack(grid), 7);
    EXPECT_FALSE(updateSdfScene(gpu, together, grid));
    const GpuScene fresh = uploadScene(together, SdfStrategy::Cells, &grid);
    EXPECT_FALSE(sdfMapCellFit(fresh.sdfMap).shallowStacks);
    EXPECT_TRUE(sdfMapCellFit(fresh.sdfMap).shortLists);

    // Moved apart again, the lists are shallow: written in place into the map for any grid.
    GpuScene anyGrid = uploadScene(together, SdfStrategy::Cells, &grid);
    ASSERT_TRUE(repruneSdfCells(*state, apart.sdf, grid));
    EXPECT_EQ(sdfDeepestCellStack(grid), 4); // (within kSdfRegisterStack)
    EXPECT_TRUE(updateSdfScene(anyGrid, apart, grid));
    expectNoGlErrors();
}
