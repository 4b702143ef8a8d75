// The inspector for a light: name and type, then the keys of its type (scene/light_spec.hpp):
// position (point, spot), direction as azimuth / elevation (directional, spot; dragging stays on
// the unit sphere), colour, intensity, range (point, spot), the cone angles (spot) and shadows,
// each with the range the scene reader accepts (see inspector.hpp).
#include "inspector.hpp"

#include "editor/light_edits.hpp"
#include "editor/param_fields.hpp"

#include "panel_widgets.hpp"
#include "scene/light_spec.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace rmsc::app {
namespace {

void drawTypeCombo(Light& light, editor::Document& document) {
    const std::string current(lightTypeName(light.type));
    if (!ImGui::BeginCombo("type", current.c_str())) return;
    for (const LightType type : kLightTypes) {
        if (ImGui::Selectable(std::string(lightTypeName(type)).c_str(), type == light.type) &&
            type != light.type) {
            light.type = type;
            document.markChanged("Light type");
        }
    }
    ImGui::EndCombo();
}

void drawDirection(Light& light, editor::Document& document) {
    const glm::vec3 d = glm::normalize(light.direction);
    float azimuth = glm::degrees(std::atan2(d.x, d.z));
    float elevation = glm::degrees(std::asin(std::clamp(-d.y, -1.0f, 1.0f)));
    bool changed = numberField("azimuth", &azimuth, 1, 0.5f, closedRange(-180, 180, Unit::Degrees),
                               "The compass direction the light comes from, about +Y (0: from "
                               "+Z).",
                               {.format = "%.1f°"});
    changed |= numberField("elevation", &elevation, 1, 0.5f, closedRange(-90, 90, Unit::Degrees),
                           "Height of the light above the horizon; 90 shines straight down.",
                           {.format = "%.1f°"});
    if (changed) {
        const float a = glm::radians(azimuth), e = glm::radians(elevation);
        light.direction =
            glm::vec3(std::sin(a) * std::cos(e), -std::sin(e), std::cos(a) * std::cos(e));
        document.markChanged("Light direction");
    }
}

// Range 0 means unlimited: a checkbox turns a limit on (at `size`) or off.
void drawRange(Light& light, editor::Document& document) {
    bool limited = light.range > 0.0f;
    if (ImGui::Checkbox("limited range", &limited)) {
        light.range = limited ? 10.0f : 0.0f;
        document.markChanged("Light range");
    }
    helpTooltip("Off: the light reaches everywhere, falling off with the square of the distance.");
    if (limited && numberField("range", &light.range, 1, stepFor(light.range), kLightRangeRange,
                               "The light reaches no farther than this."))
        document.markChanged("Light range");
}

// Inner below outer, both within the reader's ranges.
void drawCone(Light& light, editor::Document& document) {
    ParamRange inner = kSpotInnerAngleRange;
    if (double(light.outerAngleDegrees) <= inner.max) {
        inner.max = light.outerAngleDegrees;
        inner.maxExclusive = true;
    }
    if (numberField("inner angle", &light.innerAngleDegrees, 1, 0.25f, inner,
                    "Full intensity inside this angle from the axis (below the outer angle).",
                    {.format = "%.2f°"}))
        document.markChanged("Spot inner angle");
    ParamRange outer = kSpotOuterAngleRange;
    if (double(light.innerAngleDegrees) >= outer.min) {
        outer.min = light.innerAngleDegrees;
        outer.minExclusive = true;
    }
    if (numberField("outer angle", &light.outerAngleDegrees, 1, 0.25f, outer,
                    "No light outside this angle from the axis.", {.format = "%.2f°"}))
        document.markChanged("Spot outer angle");
}

// Shadows on or off; the softness is the scene's (render.shadows.softness) unless set here.
void drawShadows(Light& light, editor::Document& document) {
    if (ImGui::Checkbox("casts shadows", &light.castShadows)) document.markChanged("Light shadows");
    bool own = light.shadowSoftness > 0.0f;
    if (ImGui::Checkbox("own shadow softness", &own)) {
        light.shadowSoftness = own ? document.scene().render.shadows.softness : -1.0f;
        document.markChanged("Shadow softness");
    }
    helpTooltip("Off: the scene's shadow softness (Render tab).");
    if (own &&
        numberField("shadow softness", &light.shadowSoftness, 1, 0.001f, kLightShadowSoftnessRange,
                    "This light's SDF penumbra width factor (Quilez's k = 1 / w)."))
        document.markChanged("Shadow softness");
}

} // namespace

void drawLightInspector(editor::Document& document, int index, ViewerCommands& commands) {
    Light& light = document.editScene().lights[std::size_t(index)];
    // Unnamed, it shows the label the Scene panel gives it, greyed.
    const std::string label = editor::lightLabel(light, index);
    if (ImGui::InputTextWithHint("name", label.c_str(), &light.name))
        document.markChanged("Rename");
    drawTypeCombo(light, document);
    if (hasPosition(light.type) && numberField("position", &light.position.x, 3,
                                               stepFor(std::max(1.0f, glm::length(light.position))),
                                               unboundedRange(Unit::Metres), "Where the light is."))
        document.markChanged("Light position");
    if (hasDirection(light.type)) drawDirection(light, document);
    if (editColor("colour", light.color)) document.markChanged("Light colour");
    ParamRange intensity = kLightIntensityRange;
    intensity.unit = lightIntensityUnit(light.type);
    if (numberField("intensity", &light.intensity, 1, 0.02f, intensity,
                    light.type == LightType::Directional
                        ? "Illuminance, as glTF's KHR_lights_punctual gives it."
                        : "Luminous intensity, as glTF's KHR_lights_punctual gives it.",
                    {.format = "%.2f"}))
        document.markChanged("Light intensity");
    if (hasRange(light.type)) drawRange(light, document);
    if (hasCone(light.type)) drawCone(light, document);
    drawShadows(light, document);
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
