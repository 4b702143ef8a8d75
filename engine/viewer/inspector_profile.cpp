// The inspector's fields for a profile solid (extrusion, revolution): the profile's type and
// its parameters, the polygon's corners, and the solid's own key (depth, offset), all with the
// ranges of the profile catalogue (sdf/profiles.hpp) that the scene reader checks (see
// inspector.hpp).
#include "inspector.hpp"

#include "editor/param_fields.hpp"

#include "editor/profile_edits.hpp"
#include "panel_widgets.hpp"
#include "sdf/profiles.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

namespace rmsc::app {
namespace {

// The polygon's corners, one row each, with buttons to add a corner after one and remove one
// (within kMinPolygonPoints and kMaxPolygonPoints).
bool editPoints(std::vector<glm::vec2>& points, const SdfParamSpec& spec, float step) {
    bool changed = false;
    ImGui::TextDisabled("%s", std::string(spec.key).c_str());
    helpTooltip(spec.description);
    for (std::size_t i = 0; i < points.size(); ++i) {
        ImGui::PushID(int(i));
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
        changed |= numberField("##point", &points[i].x, 2, step, spec.range, spec.description);
        ImGui::SameLine();
        if (int(points.size()) < kMaxPolygonPoints && ImGui::SmallButton("+")) {
            // A new corner halfway to the next one.
            const glm::vec2 next = points[(i + 1) % points.size()];
            points.insert(points.begin() + std::ptrdiff_t(i) + 1, 0.5f * (points[i] + next));
            changed = true;
        }
        helpTooltip("Add a corner after this one.");
        ImGui::SameLine();
        if (int(points.size()) > kMinPolygonPoints && ImGui::SmallButton("-")) {
            points.erase(points.begin() + std::ptrdiff_t(i));
            changed = true;
            ImGui::PopID();
            break;
        }
        helpTooltip("Remove this corner.");
        ImGui::PopID();
    }
    return changed;
}

// One catalogue parameter of the profile or the solid; `cap` lowers the upper bound (a
// rounded rectangle's corner radius stays within its half size).
bool editParam(SdfProfile& profile, const ProfileParam& param, float step, float cap = FLT_MAX) {
    const SdfParamSpec& spec = param.spec;
    ParamRange range = spec.range;
    if (double(cap) < range.max) {
        range.max = cap;
        range.maxExclusive = false;
    }
    const std::string key(spec.key);
    bool changed = false;
    std::visit(
        [&](auto member) {
            auto& value = profile.*member;
            using Value = std::remove_reference_t<decltype(value)>;
            if constexpr (std::is_same_v<Value, float>)
                changed = numberField(key.c_str(), &value, 1, step, range, spec.description);
            else if constexpr (std::is_same_v<Value, glm::vec2>)
                changed = numberField(key.c_str(), &value.x, 2, step, range, spec.description);
            else
                changed = editPoints(value, spec, step);
        },
        param.field);
    return changed;
}

} // namespace

bool editProfile(SdfProfile& profile, float size) {
    bool changed = false;
    const ProfileSpec& spec = profileSpec(profile.type);
    if (ImGui::BeginCombo("profile", std::string(spec.name).c_str())) {
        for (const ProfileSpec& other : profileCatalogue()) {
            if (ImGui::Selectable(std::string(other.name).c_str(), other.type == spec.type) &&
                other.type != spec.type) {
                editor::changeProfileType(profile, other.type);
                changed = true;
            }
            helpTooltip(other.description);
        }
        ImGui::EndCombo();
    }
    helpTooltip(spec.description);
    const float step = stepFor(std::max(size, 0.1f));
    const ProfileSpec& now = profileSpec(profile.type);
    for (const ProfileParam& param : now.params) {
        const bool cornerRadius =
            profile.type == SdfProfileType::RoundedRectangle && param.spec.key == "radius";
        changed |=
            editParam(profile, param, step,
                      cornerRadius ? std::min(profile.halfSize.x, profile.halfSize.y) : FLT_MAX);
    }
    changed |= editParam(profile, profileSolidSpec(profile.solid).param, step);
    return changed;
}

} // namespace rmsc::app
