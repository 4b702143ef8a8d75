// Progressive refinement of the viewer's image (see refinement.hpp).
#include "editor/refinement.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

void Refinement::restart(int height, float estimateMilliseconds) {
    const int tileRows = (std::max(0, height) + kRowStep - 1) / kRowStep;
    if (height != height_ || int(tileRowCost_.size()) != tileRows)
        tileRowCost_.assign(tileRows, 0.0f);
    height_ = std::max(0, height);
    rows_ = 0;
    postRows_ = 0;
    if (height_ > 0 && estimateMilliseconds > 0.0f)
        msPerRow_ = std::max(msPerRow_, estimateMilliseconds / float(height_));
    // The kept costs, scaled up when the quick render says the image got dearer.
    float kept = 0.0f;
    int measured = 0;
    for (float c : tileRowCost_)
        if (c > 0.0f) kept += c, ++measured;
    costRatio_ = 1.0f;
    if (measured > 0 && height_ > 0 && estimateMilliseconds > 0.0f)
        costRatio_ =
            std::max(1.0f, estimateMilliseconds / float(height_) / (kept / float(measured)));
}

void Refinement::finish(int height, float milliseconds) {
    height_ = std::max(0, height);
    rows_ = postRows_ = height_;
    if (height_ > 0 && milliseconds > 0.0f) msPerRow_ = milliseconds / float(height_);
    tileRowCost_.assign((height_ + kRowStep - 1) / kRowStep, msPerRow_);
}

float Refinement::expectedMsPerRow(int tileRow) const {
    const float kept =
        tileRow < int(tileRowCost_.size()) ? tileRowCost_[std::size_t(tileRow)] : 0.0f;
    // Never below the recent mean: kept costs come from another view (a camera that moved).
    return kept > 0.0f ? std::max(kept * costRatio_, msPerRow_) : msPerRow_;
}

RefineBand Refinement::nextBand(float budgetMilliseconds, bool all) const {
    RefineBand band;
    band.begin = rows_;
    band.postBegin = postRows_;
    if (rows_ >= height_) {
        band.end = rows_;
    } else if (all || msPerRow_ <= 0.0f) {
        band.end = height_;
    } else {
        // Whole tile rows while their expected cost fits a share of the budget (bands start on
        // tile rows): a band's time varies by about a fifth from what its rows are expected to
        // cost (measured in the viewer's timing runs on llvmpipe).
        const float budget = kBudgetShare * budgetMilliseconds;
        int end = rows_;
        float cost = 0.0f;
        while (end < height_) {
            const int rows = std::min(kRowStep, height_ - end);
            const float next = cost + expectedMsPerRow(end / kRowStep) * float(rows);
            if (end > rows_ && next > budget) break;
            cost = next;
            end += rows;
        }
        band.end = end;
    }
    band.postEnd = band.end >= height_ ? height_ : std::max(postRows_, band.end - kPostLag);
    return band;
}

void Refinement::rendered(const RefineBand& band, float milliseconds) {
    rows_ = std::max(rows_, band.end);
    postRows_ = std::max(postRows_, band.postEnd);
    const int rows = band.end - band.begin;
    if (rows <= 0 || milliseconds <= 0.0f) return;
    const float measured = milliseconds / float(rows);
    // Half way to each new measurement: timings on a busy machine are noisy.
    msPerRow_ = msPerRow_ > 0.0f ? 0.5f * (msPerRow_ + measured) : measured;
    // What the kept costs gave for these rows, against what they cost now; then the rows' costs.
    float kept = 0.0f;
    bool known = true;
    for (int t = band.begin / kRowStep; t * kRowStep < band.end; ++t) {
        const float c = t < int(tileRowCost_.size()) ? tileRowCost_[std::size_t(t)] : 0.0f;
        known = known && c > 0.0f;
        kept += c * float(std::min(kRowStep, band.end - t * kRowStep));
    }
    // Up at once, down half way (a band over the budget is a frame over the target).
    if (known && kept > 0.0f) {
        const float ratio = milliseconds / kept;
        costRatio_ = ratio > costRatio_ ? ratio : 0.5f * (costRatio_ + ratio);
    }
    // The band's cost shared among its tile rows: in proportion to what they cost before (the
    // shape learned from earlier bands' edges stays), else evenly.
    const float share = known && kept > 0.0f ? milliseconds / kept : 0.0f;
    for (int t = band.begin / kRowStep; t * kRowStep < band.end; ++t)
        if (t < int(tileRowCost_.size()))
            tileRowCost_[std::size_t(t)] =
                share > 0.0f ? tileRowCost_[std::size_t(t)] * share : measured;
}

} // namespace rmsc::editor
