// Which keys of the scene format the inspector edits, by the schema definition that holds them
// ("group", "shape_sphere", "modifier_repeat", "light_spot", "render", "sky_image", ...), each
// with the label of its control, and the keys it deliberately leaves to another part of the
// editor. Shape, modifier and profile parameters come from their catalogues, the same rows the
// inspector draws a field for; the rest are listed by hand next to the controls. A unit test
// walks every object of the schema and fails for a key that is in neither list. GL-free.
#pragma once

#include <string>
#include <vector>

namespace rmsc::editor {

struct InspectorKey {
    std::string object;  // the schema definition ("$defs" name), or kSceneObject
    std::string key;     // its property
    std::string control; // the inspector's control for it, or why it has none
};

// The keys the inspector edits.
std::vector<InspectorKey> inspectorKeys();
// Keys of those objects the inspector leaves alone on purpose; `control` says why.
std::vector<InspectorKey> keysNotInInspector();

// The `object` of the scene's top-level keys (the schema's own "properties", not a "$defs" entry).
inline constexpr const char* kSceneObject = "";

// The labels of the SDF node controls added for "blend" and "cut".
inline constexpr const char* kBlendControl = "blend";
inline constexpr const char* kCutControl = "cut: subtracted from its siblings";

} // namespace rmsc::editor
