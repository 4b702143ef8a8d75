// Small widgets the panels share: hover help, number fields that say their unit and range and
// show when a typed value was clamped, drag steps that follow an object's size, the transform
// fields, colours in sRGB, and the buttons that duplicate or delete the selection.
#pragma once

#include "editor/param_fields.hpp"
#include "scene/scene.hpp"
#include "sdf/param_spec.hpp"
#include "viewer_commands.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>

namespace rmsc::app {

// Shows `text` (if any) while the last widget is hovered.
void helpTooltip(std::string_view text);
// A drag step that follows the size of what is edited (1% of it), never below 0.001.
float stepFor(float size);
// Position, rotation (Euler degrees) and scale; `world` shows the position in world space
// (through `parentWorld`). Returns true when anything changed.
bool editTransform(Transform& t, bool world, const glm::mat4& parentWorld, float size);
// A linear colour shown and edited in sRGB (core/srgb.hpp), so the picker's numbers and hex
// code are those a scene file's "#rrggbb" gives; `flags` are ImGuiColorEditFlags. Returns true
// when it changed.
bool editColor(const char* label, glm::vec3& linear, int flags = 0);
// How a number field is drawn besides its range: the printf format, extra ImGuiSliderFlags
// (never AlwaysClamp: the field clamps typed values itself, and says so), narrower bounds for
// dragging than the valid range (a field of fov drags within 1..179 degrees), a slider instead
// of a drag.
struct NumberFieldStyle {
    const char* format = "%.3f";
    int flags = 0;
    std::optional<editor::FloatFieldRange> drag = std::nullopt;
    bool slider = false; // only for one float with finite ends
};

// A field of `components` (1 to 4) numbers of a catalogue row or spec, each within `range` (the
// values the scene reader accepts, with their unit): dragging stays within it, and a value typed
// outside it (Ctrl+click or double-click to type) is clamped to it and the field shows "clamped
// to ..." under it for a few seconds (editor/param_fields.hpp). Hovering shows `help`, the unit
// and the range. Returns true when a value changed.
bool numberField(const char* label, float* values, int components, float step,
                 const ParamRange& range, std::string_view help,
                 const NumberFieldStyle& style = {});
bool numberField(const char* label, int* values, int components, float step,
                 const ParamRange& range, std::string_view help);
// Duplicate and Delete, side by side.
void drawDuplicateDeleteButtons(ViewerCommands& commands);

} // namespace rmsc::app
