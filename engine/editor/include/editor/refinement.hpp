// Progressive refinement of the viewer's image: after a change the view shows a quick render at
// a reduced scale, and the full-resolution image is then rendered in bands of rows over the
// following frames, each band sized to fit the frame's render budget, until it is whole. A
// change restarts it. Rows do not cost alike (the sky is cheap, the horizon dear), so the cost
// of each tile row is kept from the bands that rendered it, and the next refinement sizes its
// bands by those costs, scaled by how its own bands compare with them. GL-free: it plans, the
// viewer renders.
#pragma once

#include <vector>

namespace rmsc::editor {

// Rows of the full-resolution image, counted from the bottom (GL's order).
struct RefineBand {
    int begin = 0, end = 0;         // rows rendered: sky, meshes, shells, cones, the march
    int postBegin = 0, postEnd = 0; // rows tone-mapped; they lag `end` by kPostLag rows, so a
                                    // filter that reads neighbours (FXAA) reads finished rows
    bool empty() const { return end <= begin; }
};

class Refinement {
  public:
    static constexpr int kRowStep = 8; // bands start and end on the cone pass's 8-pixel tiles
    static constexpr int kPostLag = 16;
    static constexpr float kBudgetShare = 0.85f; // of the budget a band is planned to take

    // A change: the image of `height` rows is rendered again from row 0. `estimateMilliseconds`
    // is what a whole render is thought to cost (from a preview), 0 when unknown; the larger of
    // it and what the bands measured so far sizes the first band.
    void restart(int height, float estimateMilliseconds);
    // The whole image was rendered at once, in `milliseconds`.
    void finish(int height, float milliseconds);

    bool done() const { return postRows_ >= height_; }
    int shownRows() const { return postRows_; } // rows of the refined image that can be shown
    int height() const { return height_; }
    // The next band: as many rows as fit `budgetMilliseconds` at their expected cost (at least
    // kRowStep); with `all`, every row left.
    RefineBand nextBand(float budgetMilliseconds, bool all = false) const;
    // `band` was rendered in `milliseconds`: learns the cost per row.
    void rendered(const RefineBand& band, float milliseconds);
    // What a whole render costs at the measured rate; 0 before anything was measured.
    float fullMilliseconds() const { return msPerRow_ * float(height_); }

  private:
    int height_ = 0;
    int rows_ = 0;     // rows rendered
    int postRows_ = 0; // rows tone-mapped
    float msPerRow_ = 0.0f;
    // Per tile row (kRowStep rows): milliseconds per row when its band was last rendered (0:
    // never), and this refinement's bands' cost over what those gave for the same rows.
    std::vector<float> tileRowCost_;
    float costRatio_ = 1.0f;
    float expectedMsPerRow(int tileRow) const;
};

} // namespace rmsc::editor
