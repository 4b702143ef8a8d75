// The profile catalogue rows (sdf/profiles.hpp).
#include "sdf/profiles.hpp"

#include "core/number_text.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rmsc {
namespace {

constexpr double kBig = 1.0e4; // upper bound of lengths in the scene format

constexpr ProfileParam kCircle[] = {
    {{.key = "radius",
      .type = ParamType::Number,
      .value = {0.5f},
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "radius"},
     &SdfProfile::radius},
};

constexpr ProfileParam kRectangle[] = {
    {{.key = "half_size",
      .type = ParamType::Vec2,
      .value = {0.5f, 0.5f},
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "half the width (x) and height (y)"},
     &SdfProfile::halfSize},
};

constexpr ProfileParam kRoundedRectangle[] = {
    {{.key = "half_size",
      .type = ParamType::Vec2,
      .value = {0.5f, 0.5f},
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "half the width (x) and height (y)"},
     &SdfProfile::halfSize},
    {{.key = "radius",
      .type = ParamType::Number,
      .value = {0.1f},
      .range = closedRange(0.0, kBig, Unit::Metres),
      .description = "corner radius, at most the smaller half size"},
     &SdfProfile::radius},
};

void checkRoundedRectangle(const SdfProfile& profile, unsigned readOk,
                           std::vector<ParamProblem>& problems) {
    const float smaller = std::min(profile.halfSize.x, profile.halfSize.y);
    if ((readOk & 3u) == 3u && profile.radius > smaller)
        problems.push_back({"radius", -1,
                            "the corner radius " + shortestNumberText(profile.radius) +
                                " is larger than the smaller half size " +
                                shortestNumberText(smaller)});
}

constexpr ProfileParam kPolygon[] = {
    {{.key = "points",
      .type = ParamType::Points,
      .required = true,
      .range = closedRange(-kBig, kBig, Unit::Metres),
      .description = "the polygon's corners, [[x, y], ...]"},
     &SdfProfile::points},
};

void checkPolygon(const SdfProfile& profile, unsigned readOk, std::vector<ParamProblem>& problems) {
    if (!(readOk & 1u)) return;
    // Shoelace formula: twice the signed area.
    double area = 0.0;
    for (std::size_t i = 0; i < profile.points.size(); ++i) {
        const glm::vec2 a = profile.points[i];
        const glm::vec2 b = profile.points[(i + 1) % profile.points.size()];
        area += double(a.x) * b.y - double(b.x) * a.y;
    }
    if (!(std::abs(area) > 1e-12))
        problems.push_back({"points", -1,
                            "the polygon's points enclose no area (they are collinear or "
                            "repeated)"});
}

// In SdfProfileType order.
const ProfileSpec kCatalogue[] = {
    {SdfProfileType::Circle, "circle", kCircle, "a circle around the origin"},
    {SdfProfileType::Rectangle, "rectangle", kRectangle, "an axis-aligned rectangle"},
    {SdfProfileType::RoundedRectangle, "rounded_rectangle", kRoundedRectangle,
     "a rectangle with rounded corners (outer size given)", checkRoundedRectangle},
    {SdfProfileType::Polygon, "polygon", kPolygon,
     "a simple polygon enclosing some area (inside by the even-odd rule)", checkPolygon},
};

// In SdfProfileSolid order.
const ProfileSolidSpec kSolids[] = {
    {SdfProfileSolid::Extrusion,
     "extrusion",
     "extrude",
     {{.key = "depth",
       .type = ParamType::Number,
       .value = {0.5f},
       .range = openClosedRange(0.0, kBig, Unit::Metres),
       .description = "the full depth along z, centred on the profile's plane"},
      &SdfProfile::depth},
     "the profile (in the xy plane) extruded along z"},
    {SdfProfileSolid::Revolution,
     "revolution",
     "revolve",
     {{.key = "offset",
       .type = ParamType::Number,
       .value = {0.0f},
       .range = closedRange(0.0, kBig, Unit::Metres),
       .description = "the distance of the profile's x = 0 from the y axis"},
      &SdfProfile::offset},
     "the profile (x outwards, y up) revolved around the y axis"},
};

} // namespace

std::span<const ProfileSpec> profileCatalogue() {
    return kCatalogue;
}

const ProfileSpec& profileSpec(SdfProfileType type) {
    assert(std::size_t(type) < std::size(kCatalogue) && kCatalogue[std::size_t(type)].type == type);
    return kCatalogue[std::size_t(type)];
}

const ProfileSpec* findProfile(std::string_view name) {
    for (const ProfileSpec& spec : kCatalogue)
        if (spec.name == name) return &spec;
    return nullptr;
}

std::vector<std::string> profileNames() {
    std::vector<std::string> names;
    for (const ProfileSpec& spec : kCatalogue)
        names.emplace_back(spec.name);
    return names;
}

std::span<const ProfileSolidSpec> profileSolidCatalogue() {
    return kSolids;
}

const ProfileSolidSpec& profileSolidSpec(SdfProfileSolid solid) {
    assert(std::size_t(solid) < std::size(kSolids) && kSolids[std::size_t(solid)].solid == solid);
    return kSolids[std::size_t(solid)];
}

const ProfileSolidSpec* findProfileSolid(std::string_view name) {
    for (const ProfileSolidSpec& spec : kSolids)
        if (spec.name == name) return &spec;
    return nullptr;
}

} // namespace rmsc
