// The viewer's quick render scale and progressive refinement (editor/adaptive_scale.hpp,
// editor/refinement.hpp): bands that cover the image once, sized to the budget, and a scale
// that fits the budget right after a change.
#include "editor/adaptive_scale.hpp"
#include "editor/refinement.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rmsc::editor;

TEST(AdaptiveScale, FitsTheBudgetAtOnceAndGrowsBackSlowly) {
    AdaptiveScale a;
    a.scale = 1.0f;
    // A render of the whole image took four times the budget: a quarter of the pixels.
    EXPECT_FLOAT_EQ(a.next(132.0f, 1.0f, 33.0f), 0.5f);
    // Cheaper now (0.4 of the budget at 1/2; 0.79 would fit): up half way, not all of it.
    const float up = a.next(13.2f, 0.5f, 33.0f);
    EXPECT_FLOAT_EQ(up, 0.625f);
    // Nothing measured: the scale stays.
    EXPECT_FLOAT_EQ(a.next(0.0f, 1.0f, 33.0f), up);
    // Very slow: never below the minimum.
    EXPECT_FLOAT_EQ(a.next(1.0e6f, 1.0f, 33.0f), a.minScale);
    a.enabled = false;
    EXPECT_FLOAT_EQ(a.next(1.0e6f, 1.0f, 33.0f), 1.0f);
}

TEST(Refinement, BandsCoverEveryRowOnceWithinTheBudget) {
    Refinement r;
    const int height = 720;
    const float costPerRow = 0.4f; // a whole render: 288 ms
    r.restart(height, costPerRow * height);
    EXPECT_FALSE(r.done());
    EXPECT_EQ(r.shownRows(), 0);
    int rows = 0, posts = 0, bands = 0;
    while (!r.done() && bands < 1000) {
        const RefineBand band = r.nextBand(20.0f);
        ASSERT_FALSE(band.empty());
        EXPECT_EQ(band.begin, rows); // contiguous, from the bottom
        EXPECT_EQ(band.postBegin, posts);
        EXPECT_EQ(band.begin % Refinement::kRowStep, 0);
        EXPECT_TRUE(band.end % Refinement::kRowStep == 0 || band.end == height);
        EXPECT_LE(float(band.end - band.begin) * costPerRow, 20.0f); // fits the budget
        // The tone-mapped rows stay behind the rendered ones, but for the last band.
        EXPECT_TRUE(band.postEnd <= band.end - Refinement::kPostLag || band.end == height);
        r.rendered(band, float(band.end - band.begin) * costPerRow);
        rows = band.end;
        posts = band.postEnd;
        EXPECT_EQ(r.shownRows(), posts);
        ++bands;
    }
    EXPECT_TRUE(r.done());
    EXPECT_EQ(rows, height);
    EXPECT_EQ(posts, height);
    EXPECT_GE(bands, 15); // 288 ms in bands of at most 20 ms
    EXPECT_NEAR(r.fullMilliseconds(), costPerRow * height, 1e-3f);
}

TEST(Refinement, LearnsTheCostAndRestartsOnAChange) {
    Refinement r;
    r.restart(400, 40.0f); // thought to cost 0.1 ms a row
    RefineBand band = r.nextBand(10.0f);
    EXPECT_EQ(band.end, 80);     // 85 rows fit the share of the budget a band is planned for
    r.rendered(band, 80 * 0.4f); // four times dearer
    band = r.nextBand(10.0f);
    EXPECT_LT(band.end - band.begin, 80); // smaller bands from now on
    r.restart(400, 0.0f);                 // a change mid-refinement
    EXPECT_EQ(r.shownRows(), 0);
    EXPECT_EQ(r.nextBand(10.0f).begin, 0);
    const RefineBand all = r.nextBand(10.0f, true);
    EXPECT_EQ(all.end, 400);
    EXPECT_EQ(all.postEnd, 400);
    r.rendered(all, 1.0f);
    EXPECT_TRUE(r.done());
    // An image rendered whole at once is done.
    r.restart(300, 0.0f);
    r.finish(300, 9.0f);
    EXPECT_TRUE(r.done());
    EXPECT_EQ(r.shownRows(), 300);
}

// Rows that do not cost alike: a dear band across the middle (a horizon, twenty times the cost
// of the other rows here). The first refinement, which knows only the mean cost, goes far over
// the budget where its band reaches the dear rows; each band's cost is then shared among its
// tile rows in proportion to what they cost before, so repeated refinements of the same view (a
// camera held still between small moves) learn where the cost lies, and from the fourth on no
// band goes over. Sizing by the mean cost per row alone goes over in every one.
TEST(Refinement, LaterRefinementsSizeTheirBandsByEachRowsCost) {
    const int height = 400;
    const auto rowCost = [](int row) { return row >= 200 && row < 264 ? 1.0f : 0.05f; };
    const auto bandCost = [&](const RefineBand& band) {
        float ms = 0.0f;
        for (int row = band.begin; row < band.end; ++row)
            ms += rowCost(row);
        return ms;
    };
    float whole = 0.0f;
    for (int row = 0; row < height; ++row)
        whole += rowCost(row);
    const float budget = 12.0f;
    Refinement r;
    for (int pass = 0; pass < 6; ++pass) {
        r.restart(height, whole);
        int bands = 0;
        float worst = 0.0f;
        while (!r.done() && bands < 1000) {
            const RefineBand band = r.nextBand(budget);
            const float ms = bandCost(band);
            worst = std::max(worst, ms);
            r.rendered(band, ms);
            ++bands;
        }
        ASSERT_TRUE(r.done());
        SCOPED_TRACE(pass);
        if (pass == 0) {
            EXPECT_GT(worst, 3.0f * budget); // the mean cost per row
        }
        if (pass >= 3) {
            EXPECT_LE(worst, budget);
        }
        // 81 ms of rows, bands planned for 85% of 12 ms: 8 at the fewest; twice that at most.
        EXPECT_LE(bands, 16);
    }
}
