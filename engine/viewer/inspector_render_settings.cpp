// The inspector's render settings (Render tab): march steps and distance, surface epsilon, the
// environment (background, ambient) and exposure (see inspector.hpp).
#include "inspector.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>

namespace rmsc::app {

void drawRenderSettingsInspector(editor::Document& document) {
    RenderSettings& r = document.editScene().render;
    bool changed = false;
    changed |=
        ImGui::DragInt("max steps", &r.maxSteps, 1.0f, 1, 4096, "%d", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::DragFloat("max distance", &r.maxDistance, 0.5f, 0.1f, 10000.0f, "%.1f",
                                ImGuiSliderFlags_AlwaysClamp);
    changed |=
        ImGui::DragFloat("surface epsilon", &r.surfaceEpsilon, 0.00005f, 0.000001f, 0.1f, "%.6f",
                         ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
    changed |= editColor("background", r.background);
    changed |= editColor("ambient", r.ambient);
    changed |= ImGui::DragFloat("exposure", &r.exposure, 0.01f, 0.0f, 100.0f, "%.2f",
                                ImGuiSliderFlags_AlwaysClamp);
    if (changed) document.markChanged("Render settings");
}

} // namespace rmsc::app
