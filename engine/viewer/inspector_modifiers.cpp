// The inspector's modifiers of an SDF node, in the order they apply (docs/scene-format.md,
// "Modifiers"): each with a remove button and one field per parameter of its catalogue row
// (sdf/modifiers.hpp), then a menu to add one. A field's kind follows the parameter's type,
// its range is the one the reader accepts (editor/param_fields.hpp) and its help the row's
// description; an edit that the row's own check refuses (taper: |amount| x radius below 1) is
// undone, with the reason shown.
#include "inspector.hpp"

#include "editor/param_fields.hpp"
#include "panel_widgets.hpp"
#include "sdf/modifiers.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

namespace rmsc::app {
namespace {

// "half_extents" -> "half extents".
std::string labelOf(std::string_view key) {
    std::string label(key);
    std::replace(label.begin(), label.end(), '_', ' ');
    return label;
}

// A drag step that follows the value and the object's size.
float dragStep(const float* values, int count, float size) {
    float magnitude = 0.0f;
    for (int c = 0; c < count; ++c)
        magnitude = std::max(magnitude, std::abs(values[c]));
    return stepFor(std::max(magnitude, 0.1f * size));
}

// Three checkboxes, at least one of them on (an empty "axes" is refused by the reader).
bool editAxes(glm::bvec3& axes) {
    const glm::bvec3 before = axes;
    bool changed = false;
    for (int c = 0; c < 3; ++c) {
        if (c) ImGui::SameLine();
        bool on = axes[c];
        if (ImGui::Checkbox(std::string(1, "xyz"[c]).c_str(), &on)) {
            axes[c] = on;
            changed = true;
        }
    }
    if (!glm::any(axes)) axes = before;
    return changed && axes != before;
}

// The field of one catalogue parameter of `m`.
bool editParam(const ModifierParam& param, SdfModifier& m, float size) {
    const SdfParamSpec& spec = param.spec;
    const std::string label = labelOf(spec.key);
    const bool changed = std::visit(
        [&](auto member) -> bool {
            auto& value = m.*member;
            using T = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<T, float>) {
                return numberField(label.c_str(), &value, 1, dragStep(&value, 1, size), spec.range,
                                   spec.description, {.format = "%.4f"});
            } else if constexpr (std::is_same_v<T, glm::vec3>) {
                return numberField(label.c_str(), &value.x, 3, dragStep(&value.x, 3, size),
                                   spec.range, spec.description, {.format = "%.4f"});
            } else if constexpr (std::is_same_v<T, int>) {
                if (spec.type == ParamType::Axis) {
                    const bool picked = ImGui::Combo(label.c_str(), &value, "x\0y\0z\0");
                    helpTooltip(spec.description);
                    return picked;
                }
                return numberField(label.c_str(), &value, 1, 0.1f, spec.range, spec.description);
            } else if constexpr (std::is_same_v<T, glm::ivec3>) {
                return numberField(label.c_str(), &value.x, 3, 0.1f, spec.range, spec.description);
            } else if constexpr (std::is_same_v<T, bool>) {
                const bool toggled = ImGui::Checkbox(label.c_str(), &value);
                helpTooltip(spec.description);
                return toggled;
            } else {
                static_assert(std::is_same_v<T, glm::bvec3>);
                const bool picked = editAxes(value);
                helpTooltip(spec.description);
                return picked;
            }
        },
        param.field);
    return changed;
}

// What the row's check finds wrong with `m` beyond each parameter's range ("" for nothing).
std::string problemOf(const SdfModifier& m) {
    const ModifierSpec& spec = modifierSpec(m.type);
    if (!spec.check) return "";
    std::vector<ParamProblem> problems;
    spec.check(m, ~0u, problems);
    return problems.empty() ? "" : std::string(problems[0].key) + ": " + problems[0].message;
}

// Each number of `m` moved into its field's range.
void clampToRanges(SdfModifier& m) {
    for (const ModifierParam& param : modifierSpec(m.type).params) {
        const editor::FloatFieldRange f = editor::floatFieldRange(param.spec.range);
        const editor::IntFieldRange i = editor::intFieldRange(param.spec.range);
        std::visit(
            [&](auto member) {
                auto& value = m.*member;
                using T = std::decay_t<decltype(value)>;
                if constexpr (std::is_same_v<T, float> || std::is_same_v<T, glm::vec3>)
                    value = glm::clamp(value, f.min, f.max);
                else if constexpr (std::is_same_v<T, glm::ivec3>)
                    value = glm::clamp(value, i.min, i.max);
                else if constexpr (std::is_same_v<T, int>)
                    if (param.spec.type != ParamType::Axis) value = std::clamp(value, i.min, i.max);
            },
            param.field);
    }
}

} // namespace

bool editModifiers(SdfNode& node, float size, std::string& refusal) {
    bool changed = false;
    ImGui::TextDisabled("Modifiers");
    for (std::size_t i = 0; i < node.modifiers.size(); ++i) {
        SdfModifier& m = node.modifiers[i];
        const ModifierSpec& spec = modifierSpec(m.type);
        ImGui::PushID(int(i));
        ImGui::Text("%zu. %s", i + 1, std::string(spec.name).c_str());
        helpTooltip(spec.description);
        ImGui::SameLine();
        if (ImGui::SmallButton("remove")) {
            node.modifiers.erase(node.modifiers.begin() + std::ptrdiff_t(i));
            ImGui::PopID();
            return true;
        }
        for (const ModifierParam& param : spec.params) {
            const SdfModifier before = m;
            if (!editParam(param, m, size)) continue;
            if (std::string problem = problemOf(m); !problem.empty()) {
                m = before;
                refusal = "not applied: " + problem;
            } else {
                refusal.clear();
                changed = true;
            }
        }
        ImGui::PopID();
    }
    if (!refusal.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", refusal.c_str());
    if (ImGui::BeginCombo("add modifier", "...")) {
        for (const ModifierSpec& spec : modifierCatalogue()) {
            if (!ImGui::Selectable(std::string(spec.name).c_str())) continue;
            SdfModifier m = defaultModifier(spec.type);
            // Values that show the effect at the object's size.
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
            clampToRanges(m);
            node.modifiers.push_back(m);
            changed = true;
        }
        ImGui::EndCombo();
    }
    return changed;
}

} // namespace rmsc::app
