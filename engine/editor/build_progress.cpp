// The shader build's progress as the overlay shows it (see editor/build_progress.hpp).
#include "editor/build_progress.hpp"

#include <algorithm>
#include <cstdio>

namespace rmsc::editor {

float buildProgressFraction(const BuildProgress& p) {
    if (p.total <= 0) return 0.0f;
    const float under = p.done < p.total ? 0.5f : 0.0f;
    return std::clamp((float(p.done) + under) / float(p.total), 0.0f, 1.0f);
}

std::string buildProgressText(const BuildProgress& p) {
    if (p.total <= 0) return "";
    const int current = std::min(p.done + 1, p.total);
    char text[160];
    std::snprintf(text, sizeof text, "building shaders %d of %d%s%s%s, %.1f s", current, p.total,
                  p.building.empty() ? "" : " (", p.building.c_str(), p.building.empty() ? "" : ")",
                  std::max(0.0, p.seconds));
    return text;
}

} // namespace rmsc::editor
