// Adaptive render scale (see adaptive_scale.hpp).
#include "editor/adaptive_scale.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

float AdaptiveScale::next(float lastMilliseconds, float lastScale, float budgetMilliseconds) {
    if (!enabled) {
        scale = 1.0f;
        return scale;
    }
    if (lastMilliseconds > 0.0f && lastScale > 0.0f && budgetMilliseconds > 0.0f) {
        const float wanted = lastScale * std::sqrt(budgetMilliseconds / lastMilliseconds);
        const float s = wanted < scale ? wanted : 0.5f * (scale + wanted);
        // Rounded down, so a quantized scale does not overshoot the budget.
        scale = std::clamp(std::floor(s * 16.0f) / 16.0f, minScale, 1.0f);
    }
    return scale;
}

} // namespace rmsc::editor
