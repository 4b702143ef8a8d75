// The check a save makes before it writes (see scene_check.hpp).
#include "editor/scene_check.hpp"

#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"

namespace rmsc::editor {

bool checkSceneText(std::string_view text, const std::filesystem::path& file,
                    Diagnostics& diagnostics) {
    const int errorsBefore = diagnostics.errorCount();
    const std::optional<Scene> scene = parseScene(text, file, diagnostics);
    // The compile prepareScene does for `rmsc validate` (stack and instruction limits, empty
    // groups, shells' placement).
    if (scene && scene->sdf)
        compileSdfScene(*scene->sdf, std::uint32_t(scene->materials.size()), file.string(),
                        diagnostics);
    return diagnostics.errorCount() == errorsBefore;
}

std::string firstErrors(const Diagnostics& diagnostics, int most) {
    std::string text;
    int shown = 0;
    for (const Diagnostic& d : diagnostics.items) {
        if (d.severity != Severity::Error) continue;
        if (shown == most) {
            const int more = diagnostics.errorCount() - most;
            text += "(and " + std::to_string(more) + " more error" + (more == 1 ? "" : "s") + ")\n";
            break;
        }
        text += (d.location.empty() ? "" : d.location + ": ") + d.message + "\n";
        ++shown;
    }
    return text;
}

} // namespace rmsc::editor
