// Widgets the panels share (see panel_widgets.hpp).
#include "panel_widgets.hpp"

#include "core/srgb.hpp"
#include "editor/param_fields.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace rmsc::app {

void helpTooltip(std::string_view text) {
    if (!text.empty() && ImGui::IsItemHovered())
        ImGui::SetTooltip("%.*s", int(text.size()), text.data());
}

bool dragFloatInRange(const char* label, float& value, float step, const ParamRange& range,
                      const char* format) {
    const editor::FloatFieldRange r = editor::floatFieldRange(range);
    return ImGui::DragFloat(label, &value, step, r.min, r.max, format,
                            ImGuiSliderFlags_AlwaysClamp);
}

float stepFor(float size) {
    return std::max(0.001f, std::abs(size) * 0.01f);
}

bool editTransform(Transform& t, bool world, const glm::mat4& parentWorld, float size) {
    bool changed = false;
    glm::vec3 position = world ? glm::vec3(parentWorld * glm::vec4(t.position, 1.0f)) : t.position;
    if (ImGui::DragFloat3("position", &position.x, stepFor(size))) {
        t.position =
            world ? glm::vec3(glm::inverse(parentWorld) * glm::vec4(position, 1.0f)) : position;
        changed = true;
    }
    glm::vec3 euler = glm::degrees(glm::eulerAngles(t.rotation));
    if (ImGui::DragFloat3("rotation", &euler.x, 0.5f, -360.0f, 360.0f, "%.1f°")) {
        t.rotation = glm::quat(glm::radians(euler));
        changed = true;
    }
    if (ImGui::DragFloat3("scale", &t.scale.x, 0.005f, 0.001f, 1000.0f, "%.3f",
                          ImGuiSliderFlags_AlwaysClamp))
        changed = true;
    return changed;
}

bool editColor(const char* label, glm::vec3& linear, int flags) {
    glm::vec3 shown = linearToSrgb(linear);
    if (!ImGui::ColorEdit3(label, &shown.x, flags)) return false;
    linear = srgbToLinear(shown);
    return true;
}

void drawDuplicateDeleteButtons(ViewerCommands& commands) {
    if (ImGui::Button("Duplicate")) commands.push_back(ViewerCommand::Duplicate);
    ImGui::SameLine();
    if (ImGui::Button("Delete")) commands.push_back(ViewerCommand::Delete);
}

} // namespace rmsc::app
