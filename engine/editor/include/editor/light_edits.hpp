// Lights in the editor: new lights of each type, what the move (G) and rotate (R) gestures turn
// a light into and back (its position and its direction as a Transform), clicking a light's
// marker in the view, and names for the Scene panel. GL-free.
#pragma once

#include "editor/transform_gesture.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace rmsc::editor {

// The way a light with an unrotated transform shines: straight down.
inline constexpr glm::vec3 kLightRestDirection{0.0f, -1.0f, 0.0f};

// A light of `type` named "<type> light <number>" at `position` (point and spot lights shine
// from it; a directional light's marker stands there); a spot shines straight down, a
// directional light keeps the default slanted direction. Every other key has its default.
Light makeLight(LightType type, glm::vec3 position, int number);

// Which gestures change a light of `type`: moving those that have a position (point, spot),
// rotating those that have a direction (spot, directional). Nothing scales a light.
bool gestureChangesLight(LightType type, GestureKind kind);

// The light as a gesture's transform: its position, the rotation that turns
// kLightRestDirection into its direction (none for a point light), scale 1.
Transform lightTransform(const Light& light);
// Takes the position and the direction back from `transform` (scale is ignored), each only
// where the light's type has it.
void setLightTransform(Light& light, const Transform& transform);

// The light whose marker (drawn at its position) is nearest to `mouse` (viewport pixels, y
// down) within `radiusPixels`, in front of the camera; -1 when none is.
int pickLight(const Scene& scene, const GestureView& view, glm::vec2 mouse, float radiusPixels);

// The light's name, or "<type> light <index + 1>" when it has none.
std::string lightLabel(const Light& light, int index);

} // namespace rmsc::editor
