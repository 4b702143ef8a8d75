// Adaptive render resolution: the scale of the quick render the viewer shows right after a
// change (a camera move, an edit), chosen from what the last render cost so that it fits the
// frame's render budget (fewer pixels when slow, more when fast). The full-resolution image is
// then refined over the following frames (refinement.hpp). GL-free.
#pragma once

namespace rmsc::editor {

struct AdaptiveScale {
    float targetMilliseconds = 33.0f; // the UI frame time to hold (the View menu edits it)
    float minScale = 0.125f;
    float scale = 0.25f; // the scale of the last quick render (the first: before any timing)
    bool enabled = true; // off: every change renders the full image at once

    // The scale for the next quick render, given that a render at `lastScale` took
    // `lastMilliseconds` (0: unknown) and `budgetMilliseconds` are left for it in the frame.
    // Cost grows with the pixel count, i.e. with the scale squared. Goes down at once when too
    // slow, up half way when there is room (so timing noise does not make it flicker);
    // quantized to steps of 1/16 so render targets are not reallocated every frame. 1 means the
    // whole image fits: no refinement needed.
    float next(float lastMilliseconds, float lastScale, float budgetMilliseconds);
};

} // namespace rmsc::editor
