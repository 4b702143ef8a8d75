// Adaptive render scale (see adaptive_scale.hpp).
#include "editor/adaptive_scale.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

float AdaptiveScale::next(bool viewChanged, float lastMilliseconds, float lastScale) {
    if (!enabled) {
        scale = 1.0f;
        return scale;
    }
    stillFrames = viewChanged ? 0 : stillFrames + 1;
    if (stillFrames > 2) {
        scale = 1.0f; // refine: the view is still
        return scale;
    }
    if (lastMilliseconds > 0.0f && lastScale > 0.0f) {
        // Cost grows with the pixel count, i.e. with scale squared: aim the area at the target.
        const float wanted = lastScale * std::sqrt(targetMilliseconds / lastMilliseconds);
        // Move part of the way each frame so noise in the timing does not make it flicker.
        float s = std::clamp(0.5f * (scale + wanted), minScale, 1.0f);
        if (stillFrames == 0 && lastScale >= 1.0f && lastMilliseconds <= targetMilliseconds)
            s = 1.0f;
        scale = std::clamp(std::round(s * 16.0f) / 16.0f, minScale, 1.0f);
    }
    return scale;
}

} // namespace rmsc::editor
