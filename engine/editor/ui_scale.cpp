// The panels' scale (see editor/ui_scale.hpp).
#include "editor/ui_scale.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

float uiScale(float option, float contentScaleX, float contentScaleY) {
    float scale = option;
    if (!(scale > 0.0f) || !std::isfinite(scale)) {
        const auto usable = [](float s) { return std::isfinite(s) && s > 0.0f ? s : 1.0f; };
        scale = std::max(usable(contentScaleX), usable(contentScaleY));
    }
    return std::clamp(scale, kMinUiScale, kMaxUiScale);
}

} // namespace rmsc::editor
