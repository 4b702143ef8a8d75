// Small widgets the panels share: hover help, drag steps that follow an object's size, the
// transform fields, colours in sRGB, and the buttons that duplicate or delete the selection.
#pragma once

#include "scene/scene.hpp"
#include "sdf/param_spec.hpp"
#include "viewer_commands.hpp"

#include <glm/glm.hpp>

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
// A drag field for a number of a catalogue row (sdf/param_spec.hpp ParamRange), clamped to what the
// reader accepts (editor/param_fields.hpp). Returns true when it changed.
bool dragFloatInRange(const char* label, float& value, float step, const ParamRange& range,
                      const char* format);
// Duplicate and Delete, side by side.
void drawDuplicateDeleteButtons(ViewerCommands& commands);

} // namespace rmsc::app
