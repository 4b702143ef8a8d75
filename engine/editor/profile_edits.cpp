// Profile solids in the editor (see profile_edits.hpp).
#include "editor/profile_edits.hpp"

#include "sdf/profiles.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace rmsc::editor {
namespace {

// Sets the member a parameter is read into to the parameter's catalogue default (a polygon's
// points have none: they are left as they are).
void setDefault(SdfProfile& profile, const ProfileParam& param) {
    const std::array<float, 3>& value = param.spec.value;
    std::visit(
        [&](auto member) {
            using Member = std::remove_reference_t<decltype(profile.*member)>;
            if constexpr (std::is_same_v<Member, float>)
                profile.*member = value[0];
            else if constexpr (std::is_same_v<Member, glm::vec2>)
                profile.*member = glm::vec2(value[0], value[1]);
        },
        param.field);
}

bool hasKey(const ProfileSpec& spec, std::string_view key, ParamType type) {
    return std::any_of(spec.params.begin(), spec.params.end(), [&](const ProfileParam& p) {
        return p.spec.key == key && p.spec.type == type;
    });
}

} // namespace

SdfNode makeProfileShape(SdfProfileSolid solid) {
    SdfNode node;
    const ProfileSolidSpec& solidSpec = profileSolidSpec(solid);
    node.name = std::string(solidSpec.name);
    SdfProfile profile;
    profile.solid = solid;
    profile.type = SdfProfileType::Circle;
    for (const ProfileParam& param : profileSpec(profile.type).params)
        setDefault(profile, param);
    setDefault(profile, solidSpec.param);
    if (solid == SdfProfileSolid::Revolution) profile.offset = 2.0f * profile.radius;
    node.profile = profile;
    return node;
}

void changeProfileType(SdfProfile& profile, SdfProfileType type) {
    if (profile.type == type) return;
    const ProfileSpec& from = profileSpec(profile.type);
    const ProfileSpec& to = profileSpec(type);
    for (const ProfileParam& param : to.params)
        if (!hasKey(from, param.spec.key, param.spec.type)) setDefault(profile, param);
    if (type == SdfProfileType::Polygon) {
        // A circle's half size is its radius; a rectangle's is its own.
        const glm::vec2 h =
            profile.type == SdfProfileType::Circle ? glm::vec2(profile.radius) : profile.halfSize;
        profile.points = {{-h.x, -h.y}, {h.x, -h.y}, {h.x, h.y}, {-h.x, h.y}};
    }
    if (type == SdfProfileType::RoundedRectangle)
        profile.radius = std::min(profile.radius, std::min(profile.halfSize.x, profile.halfSize.y));
    profile.type = type;
}

float profileSolidRadius(const SdfProfile& profile) {
    glm::vec2 extent(0.0f); // of the profile, from its origin
    switch (profile.type) {
    case SdfProfileType::Circle:
        extent = glm::vec2(profile.radius);
        break;
    case SdfProfileType::Rectangle:
    case SdfProfileType::RoundedRectangle:
        extent = profile.halfSize;
        break;
    case SdfProfileType::Polygon:
        for (const glm::vec2 p : profile.points)
            extent = glm::max(extent, glm::abs(p));
        break;
    }
    if (profile.solid == SdfProfileSolid::Extrusion)
        return glm::length(glm::vec3(extent, 0.5f * profile.depth));
    return glm::length(glm::vec2(profile.offset + extent.x, extent.y));
}

std::string profileShapeName(const SdfProfile& profile) {
    return std::string(profileSolidSpec(profile.solid).name);
}

} // namespace rmsc::editor
