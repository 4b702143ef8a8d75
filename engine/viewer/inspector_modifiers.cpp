// The inspector's modifiers of an SDF node, in the order they apply (docs/scene-format.md,
// "Modifiers"): each with the fields of its type and a remove button, then a menu to add one.
#include "inspector.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <iterator>

namespace rmsc::app {

bool editModifiers(SdfNode& node, float size) {
    static const char* kNames[] = {"repeat", "mirror", "polar", "elongate", "twist",
                                   "bend",   "round",  "onion", "displace"};
    bool changed = false;
    ImGui::TextDisabled("Modifiers");
    const float step = stepFor(size);
    for (std::size_t i = 0; i < node.modifiers.size(); ++i) {
        SdfModifier& m = node.modifiers[i];
        ImGui::PushID(int(i));
        ImGui::Text("%zu. %s", i + 1, kNames[int(m.type)]);
        ImGui::SameLine();
        if (ImGui::SmallButton("remove")) {
            node.modifiers.erase(node.modifiers.begin() + std::ptrdiff_t(i));
            ImGui::PopID();
            return true;
        }
        switch (m.type) {
        case SdfModifierType::Repeat:
            changed |= ImGui::DragFloat3("period", &m.vector.x, step, 0.0f, 1e4f, "%.3f",
                                         ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("Cell size per axis; 0 leaves the axis unrepeated.");
            changed |= ImGui::DragInt3("count", &m.counts.x, 0.1f, 0, 1000, "%d",
                                       ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("Copies per axis; 0 repeats without end.");
            changed |= ImGui::Checkbox("neighbours", &m.neighbours);
            break;
        case SdfModifierType::Mirror:
            changed |= ImGui::Checkbox("x", &m.axes.x);
            ImGui::SameLine();
            changed |= ImGui::Checkbox("y", &m.axes.y);
            ImGui::SameLine();
            changed |= ImGui::Checkbox("z", &m.axes.z);
            break;
        case SdfModifierType::Polar:
            changed |= ImGui::DragInt("copies", &m.count, 0.1f, 1, 1000, "%d",
                                      ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::Combo("axis", &m.axis, "x\0y\0z\0");
            break;
        case SdfModifierType::Elongate:
            changed |= ImGui::DragFloat3("half extents", &m.vector.x, step, 0.0f, 1e4f, "%.3f",
                                         ImGuiSliderFlags_AlwaysClamp);
            break;
        case SdfModifierType::Twist:
        case SdfModifierType::Bend:
            changed |= ImGui::DragFloat("degrees per unit", &m.amount, 0.5f, -3600.0f, 3600.0f,
                                        "%.1f", ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("radius", &m.radius, step, 0.0f, 1e4f, "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("How far from the axis the content reaches (sets the step correction).");
            break;
        case SdfModifierType::Round:
            changed |= ImGui::DragFloat("radius", &m.radius, step * 0.25f, 0.0f, 1e4f, "%.4f",
                                        ImGuiSliderFlags_AlwaysClamp);
            break;
        case SdfModifierType::Onion:
            changed |= ImGui::DragFloat("thickness", &m.thickness, step * 0.25f, 1e-4f, 1e4f,
                                        "%.4f", ImGuiSliderFlags_AlwaysClamp);
            break;
        case SdfModifierType::Displace:
            changed |= ImGui::DragFloat("amplitude", &m.amount, step * 0.1f, 0.0f, 1e3f, "%.4f",
                                        ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("frequency", &m.frequency, 0.05f, 1e-3f, 1e3f, "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
            break;
        }
        ImGui::PopID();
    }
    if (ImGui::BeginCombo("add modifier", "...")) {
        for (int t = 0; t < int(std::size(kNames)); ++t) {
            if (!ImGui::Selectable(kNames[t])) continue;
            SdfModifier m;
            m.type = SdfModifierType(t);
            // Defaults that show the effect at the object's size.
            m.vector = m.type == SdfModifierType::Repeat ? glm::vec3(size * 3.0f, 0.0f, 0.0f)
                                                         : glm::vec3(size * 0.5f, 0.0f, 0.0f);
            m.axes = glm::bvec3(true, false, false);
            m.count = 6;
            m.amount = m.type == SdfModifierType::Displace ? size * 0.05f : 45.0f;
            m.radius = m.type == SdfModifierType::Round ? size * 0.05f : size;
            m.thickness = size * 0.05f;
            m.frequency = 4.0f / std::max(size, 1e-3f);
            node.modifiers.push_back(m);
            changed = true;
        }
        ImGui::EndCombo();
    }
    return changed;
}

} // namespace rmsc::app
