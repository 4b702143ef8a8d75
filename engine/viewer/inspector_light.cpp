// The inspector for a directional light: name, direction as azimuth / elevation (dragging stays
// on the unit sphere), colour and intensity (see inspector.hpp).
#include "inspector.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

namespace rmsc::app {

void drawLightInspector(editor::Document& document, int index, ViewerCommands& commands) {
    Light& light = document.editScene().lights[std::size_t(index)];
    if (ImGui::InputText("name", &light.name)) document.markChanged("Rename");
    ImGui::TextDisabled("directional light");
    const glm::vec3 d = glm::normalize(light.direction);
    float azimuth = glm::degrees(std::atan2(d.x, d.z));
    float elevation = glm::degrees(std::asin(std::clamp(-d.y, -1.0f, 1.0f)));
    bool changed = ImGui::DragFloat("azimuth", &azimuth, 0.5f, -180.0f, 180.0f, "%.1f°");
    changed |= ImGui::DragFloat("elevation", &elevation, 0.5f, -90.0f, 90.0f, "%.1f°",
                                ImGuiSliderFlags_AlwaysClamp);
    helpTooltip("Height of the light above the horizon; 90 shines straight down.");
    if (changed) {
        const float a = glm::radians(azimuth), e = glm::radians(elevation);
        light.direction =
            glm::vec3(std::sin(a) * std::cos(e), -std::sin(e), std::cos(a) * std::cos(e));
        document.markChanged("Light direction");
    }
    if (editColor("colour", light.color)) document.markChanged("Light colour");
    if (ImGui::DragFloat("intensity", &light.intensity, 0.02f, 0.0f, 1000.0f, "%.2f",
                         ImGuiSliderFlags_AlwaysClamp))
        document.markChanged("Light intensity");
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
