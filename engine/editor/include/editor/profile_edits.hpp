// Profile solids (extrusion, revolution) in the editor: new ones with the profile catalogue's
// defaults (sdf/profiles.hpp), changing a profile's type, and how far a profile solid reaches
// (for framing and drag steps). GL-free.
#pragma once

#include "sdf/sdf_tree.hpp"

namespace rmsc::editor {

// A shape node making `solid` of a circle profile with every key at its catalogue default,
// named after the solid. A revolution's profile is set 2 radii out from the axis, so it is
// a ring (at the default offset 0 it would be a sphere).
SdfNode makeProfileShape(SdfProfileSolid solid);

// Gives `profile` the type `type`: keys of the same name and kind keep their values, the others
// take their catalogue defaults; a new polygon gets the corners of the rectangle the profile
// held (its half size), a rounded rectangle's corner radius is kept within the half size.
void changeProfileType(SdfProfile& profile, SdfProfileType type);

// The radius of a sphere around the origin that holds the solid, in the node's own units.
float profileSolidRadius(const SdfProfile& profile);

// "revolution", "extrusion": the solid's JSON shape name.
std::string profileShapeName(const SdfProfile& profile);

} // namespace rmsc::editor
