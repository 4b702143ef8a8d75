// The cells buffer after an edit (render/gpu_scene.hpp, updateSdfCells): the words a re-prune
// changed are written into the buffer in place, and the buffer then holds exactly the edited
// grid; a grid that does not fit gets a new buffer.
#include "gpu_test_support.hpp"

#include "render/gpu_scene.hpp"
#include "sdf/cell_pruning.hpp"

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
        EXPECT_LT(written * 10, grid.words.size()); // a small part of the grid
        updateSdfCells(gpu, grid);
        EXPECT_EQ(gpu.sdfCells.id(), buffer);
        EXPECT_EQ(gpu.sdfCellHeader.info.x, std::uint32_t(grid.levels));
        EXPECT_EQ(gpu.sdfCellHeader.info.y, grid.outsideOffset);
        EXPECT_TRUE(readCells(gpu, grid.words.size()) == expectedCells(gpu.sdfCellHeader, grid))
            << "move " << move;
    }

    // A grid larger than the buffer's room: a new buffer with all of it.
    SdfCellGrid larger = grid;
    larger.words.resize(grid.words.size() * 2, 7u);
    larger.changedWords = {{0, std::uint32_t(larger.words.size())}};
    updateSdfCells(gpu, larger);
    EXPECT_TRUE(readCells(gpu, larger.words.size()) == expectedCells(gpu.sdfCellHeader, larger));
}
