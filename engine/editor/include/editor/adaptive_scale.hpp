// Adaptive render resolution: while the view changes, the render scale follows the measured
// frame time towards a target (fewer pixels when slow, more when fast); once the view is still
// for a few frames, one frame is rendered at full resolution and kept. GL-free.
#pragma once

namespace rmsc::editor {

struct AdaptiveScale {
    float targetMilliseconds = 33.0f;
    float minScale = 0.125f;
    float scale = 1.0f;  // the scale to render the next frame at
    int stillFrames = 0; // frames since the view last changed
    bool enabled = true;

    // Call once per frame with whether the view changed and how long the last render took
    // (at the scale it was rendered with). Returns the scale for the next frame, quantized to
    // steps of 1/16 so render targets are not reallocated every frame.
    float next(bool viewChanged, float lastMilliseconds, float lastScale);
    // True when the last frame was rendered at full scale and nothing changed since: the
    // viewer can show it again instead of rendering.
    bool refined(float lastScale) const { return stillFrames > 2 && lastScale >= 1.0f; }
};

} // namespace rmsc::editor
