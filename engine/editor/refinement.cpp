// Progressive refinement of the viewer's image (see refinement.hpp).
#include "editor/refinement.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

void Refinement::restart(int height, float estimateMilliseconds) {
    height_ = std::max(0, height);
    rows_ = 0;
    postRows_ = 0;
    if (height_ > 0 && estimateMilliseconds > 0.0f)
        msPerRow_ = std::max(msPerRow_, estimateMilliseconds / float(height_));
}

void Refinement::finish(int height, float milliseconds) {
    height_ = std::max(0, height);
    rows_ = postRows_ = height_;
    if (height_ > 0 && milliseconds > 0.0f) msPerRow_ = milliseconds / float(height_);
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
        const float fit = std::floor(budgetMilliseconds / msPerRow_ / float(kRowStep));
        const int rows = kRowStep * std::max(1, int(std::min(fit, float(height_))));
        band.end = std::min(height_, rows_ + rows);
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
}

} // namespace rmsc::editor
