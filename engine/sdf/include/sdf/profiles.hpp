// The profile catalogue: one row per 2D profile (SdfProfileType: its JSON "type", parameters
// and checks) and one per solid made of a profile (SdfProfileSolid: extrusion, revolution). The
// scene reader, the writer, the schema and the docs tables read these rows; the profile's
// number is the Profile instruction's kind, whose GLSL names are generated from the rows
// (sdf/glsl_constants.hpp). Formulas: sdfProfile in shaders/common/sdf_functions.glsl and in
// engine/sdf/sdf_functions.cpp (sdf/sdf_functions.hpp).
#pragma once

#include "core/limits.hpp"
#include "sdf/param_spec.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rmsc {

// The corners a polygon profile may have.
constexpr int kMinPolygonPoints = 3;
constexpr int kMaxPolygonPoints = limits::kPolygonPoints;

// The SdfProfile member a parameter is read into (Number float, Vec2 vec2, Points the points).
using ProfileField = std::variant<float SdfProfile::*, glm::vec2 SdfProfile::*,
                                  std::vector<glm::vec2> SdfProfile::*>;

struct ProfileParam {
    SdfParamSpec spec;
    ProfileField field;
};

struct ProfileSpec {
    SdfProfileType type;
    std::string_view name; // JSON value of the profile's "type"
    std::span<const ProfileParam> params;
    std::string_view description;
    // Problems beyond each parameter's range; bit i of `readOk` is set when parameter i was
    // read without error (or left at its default). nullptr: none.
    void (*check)(const SdfProfile& profile, unsigned readOk,
                  std::vector<ParamProblem>& problems) = nullptr;
};

struct ProfileSolidSpec {
    SdfProfileSolid solid;
    std::string_view name; // JSON value of the node's "shape"
    std::string_view verb; // what it does to the profile: "extrude"
    ProfileParam param;    // its own key besides "profile"
    std::string_view description;
};

std::span<const ProfileSpec> profileCatalogue(); // in SdfProfileType order
const ProfileSpec& profileSpec(SdfProfileType type);
const ProfileSpec* findProfile(std::string_view name); // nullptr if unknown
std::vector<std::string> profileNames();

std::span<const ProfileSolidSpec> profileSolidCatalogue(); // in SdfProfileSolid order
const ProfileSolidSpec& profileSolidSpec(SdfProfileSolid solid);
const ProfileSolidSpec* findProfileSolid(std::string_view name); // nullptr if unknown

} // namespace rmsc
