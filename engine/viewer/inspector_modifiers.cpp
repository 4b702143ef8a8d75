// The inspector's modifiers of an SDF node, in the order they apply (docs/scene-format.md,
// "Modifiers"): each with the fields of its type and a remove button, then a menu to add one.
#include "inspector.hpp"

#include "panel_widgets.hpp"
#include "sdf/modifiers.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace rmsc::app {

bool editModifiers(SdfNode& node, float size) {
    bool changed = false;
    ImGui::TextDisabled("Modifiers");
    const float step = stepFor(size);
    for (std::size_t i = 0; i < node.modifiers.size(); ++i) {
        SdfModifier& m = node.modifiers[i];
        ImGui::PushID(int(i));
        ImGui::Text("%zu. %s", i + 1, std::string(modifierSpec(m.type).name).c_str());
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
        case SdfModifierType::Taper: {
            // |amount| x radius stays below 1: the scale must not reach 0 (the reader's check).
            const float most = 0.99f / std::max(m.radius, 1e-4f);
            changed |= ImGui::DragFloat("scale per unit", &m.amount, 0.01f / std::max(size, 1e-3f),
                                        -std::min(most, 100.0f), std::min(most, 100.0f), "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("radius", &m.radius, step, 1e-4f,
                                        std::min(1e4f, 0.99f / std::max(std::abs(m.amount), 1e-4f)),
                                        "%.3f", ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("How far the content reaches: from the y axis, and the height beyond "
                        "which the scale stays constant (sets the step correction).");
            break;
        }
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
        for (const ModifierSpec& spec : modifierCatalogue()) {
            if (!ImGui::Selectable(std::string(spec.name).c_str())) continue;
            SdfModifier m;
            m.type = spec.type;
            // Defaults that show the effect at the object's size.
            m.vector = m.type == SdfModifierType::Repeat ? glm::vec3(size * 3.0f, 0.0f, 0.0f)
                                                         : glm::vec3(size * 0.5f, 0.0f, 0.0f);
            m.axes = glm::bvec3(true, false, false);
            m.count = 6;
            m.amount = m.type == SdfModifierType::Displace ? size * 0.05f
                       : m.type == SdfModifierType::Taper  ? 0.5f / std::max(size, 1e-3f)
                                                           : 45.0f;
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
