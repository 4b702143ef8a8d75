// The edited scene's cells pruned on a worker (editor/cell_pruning_job.hpp): an edit of numbers
// is pruned again from the kept state into the grid the last result gave when nobody holds that
// result any more, and into a copy while someone does: a grid once given never changes.
#include "editor/cell_pruning_job.hpp"

#include "core/diagnostics.hpp"
#include "editor/scene_preparing_job.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace rmsc;

namespace {

// Eight spheres in a row, the first one at x = firstX.
Scene rowOfSpheres(float firstX) {
    std::string children;
    for (int i = 0; i < 8; ++i)
        children += (i ? ", " : "") +
                    std::string(R"({"shape": "sphere", "radius": 0.3, "position": [)") +
                    std::to_string(i == 0 ? firstX : float(i)) + ", 0, 0]}";
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(
        R"({"version": 1, "sdf": {"children": [)" + children + "]}}", "row.json", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.format();
    return scene ? *scene : Scene{};
}

// What the viewer asks for: the scene as its worker compiles it.
editor::CellPruningRequest requestFor(std::uint64_t revision, const Scene& scene) {
    editor::ScenePreparingResult prepared =
        editor::prepareEditedScene(scene, revision, diskFileSource());
    EXPECT_TRUE(prepared.prepared) << prepared.error;
    editor::CellPruningRequest request;
    request.revision = revision;
    request.scene = std::make_shared<const PreparedScene>(std::move(*prepared.prepared));
    return request;
}

editor::CellPruningResult pruned(editor::CellPruningJob& job, editor::CellPruningRequest request) {
    job.request(std::move(request));
    job.waitUntilIdle();
    std::optional<editor::CellPruningResult> result = job.take();
    EXPECT_TRUE(result);
    return result ? std::move(*result) : editor::CellPruningResult{};
}

// The cells' programs of `grid` at random points of its cube equal those of a full build of
// `request`'s program in the same cube: the one around `content` (the first build's content; a
// re-prune keeps its cube), and so do the list and the floor of points outside the grid.
void expectAFullBuildsPrograms(const SdfCellGrid& grid, const editor::CellPruningRequest& request,
                               const Aabb& content) {
    const SdfCellGrid full = buildSdfCells(request.scene->sdf, content);
    ASSERT_GT(full.levels, 0);
    ASSERT_EQ(full.origin, grid.origin);
    ASSERT_EQ(full.size, grid.size);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 p = full.origin + full.size * glm::vec3(unit(rng), unit(rng), unit(rng));
        const std::span<const std::uint32_t> a = sdfCellWords(grid, sdfCellRange(grid, p)),
                                             b = sdfCellWords(full, sdfCellRange(full, p));
        ASSERT_EQ(std::vector<std::uint32_t>(a.begin(), a.end()),
                  std::vector<std::uint32_t>(b.begin(), b.end()))
            << "at (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
    const auto outsideList = [](const SdfCellGrid& g) {
        const auto list =
            std::span(g.words).subspan(g.outsideOffset, sdfListWords(g.outsideLength, g.reading));
        return std::vector<std::uint32_t>(list.begin(), list.end());
    };
    EXPECT_EQ(outsideList(grid), outsideList(full));
    ASSERT_EQ(grid.outsideFloor.has_value(), full.outsideFloor.has_value());
    if (full.outsideFloor) {
        EXPECT_EQ(grid.outsideFloor->box.min, full.outsideFloor->box.min);
        EXPECT_EQ(grid.outsideFloor->box.max, full.outsideFloor->box.max);
        EXPECT_EQ(grid.outsideFloor->drop, full.outsideFloor->drop);
    }
}

} // namespace

TEST(CellPruningJob, AHeldGridNeverChangesAndAReleasedOneIsPrunedInPlace) {
    editor::CellPruningJob job;
    const editor::CellPruningRequest start = requestFor(1, rowOfSpheres(0.0f));
    const Aabb content = sdfContentBox(*start.scene->scene.sdf);
    std::optional<editor::CellPruningResult> first = pruned(job, start);
    ASSERT_TRUE(first->grid);
    EXPECT_FALSE(first->again);
    const std::vector<std::uint32_t> firstWords = first->grid->words;

    // An edit while the first result is held: pruned again into a copy.
    const editor::CellPruningRequest moved = requestFor(2, rowOfSpheres(0.4f));
    std::optional<editor::CellPruningResult> second = pruned(job, moved);
    ASSERT_TRUE(second->grid);
    EXPECT_TRUE(second->again);
    EXPECT_NE(second->grid.get(), first->grid.get());
    EXPECT_EQ(first->grid->words, firstWords); // the held grid is as it was given
    EXPECT_NE(second->grid->words, firstWords);
    expectAFullBuildsPrograms(*second->grid, moved, content);

    // Both let go: the next edit is pruned into the second's grid itself.
    const SdfCellGrid* secondGrid = second->grid.get();
    first.reset();
    second.reset();
    const editor::CellPruningRequest back = requestFor(3, rowOfSpheres(0.0f));
    const editor::CellPruningResult third = pruned(job, back);
    ASSERT_TRUE(third.grid);
    EXPECT_TRUE(third.again);
    EXPECT_EQ(third.grid.get(), secondGrid);
    expectAFullBuildsPrograms(*third.grid, back, content);
}
