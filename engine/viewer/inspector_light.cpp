// The inspector for a light: name and type, then the keys of its type (scene/light_spec.hpp):
// position (point, spot), direction as azimuth / elevation (directional, spot; dragging stays on
// the unit sphere), colour, intensity, range (point, spot), the cone angles (spot) and shadows,
// each with the range the scene reader accepts (see inspector.hpp).
#include "inspector.hpp"

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

// The bounds a drag keeps a number within so the reader accepts it: an exclusive end moves to
// the next float inside, an unbounded end to the largest float.
struct DragBounds {
    float min = -FLT_MAX, max = FLT_MAX;
};

DragBounds dragBounds(const ParamRange& range) {
    const editor::FloatFieldRange r = editor::floatFieldRange(range);
    return {r.min, r.max};
}

bool dragNumber(const char* label, float& value, float step, DragBounds bounds,
                const char* format) {
    return ImGui::DragFloat(label, &value, step, bounds.min, bounds.max, format,
                            ImGuiSliderFlags_AlwaysClamp);
}

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
    bool changed = ImGui::DragFloat("azimuth", &azimuth, 0.5f, -180.0f, 180.0f, "%.1f°");
    changed |= ImGui::DragFloat("elevation", &elevation, 0.5f, -90.0f, 90.0f, "%.1f°",
                                ImGuiSliderFlags_AlwaysClamp);
    helpTooltip("Height of the light above the horizon; 90 shines straight down.");
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
    if (limited && dragNumber("range", light.range, stepFor(light.range),
                              dragBounds(kLightRangeRange), "%.3f"))
        document.markChanged("Light range");
}

// Inner below outer, both within the reader's ranges.
void drawCone(Light& light, editor::Document& document) {
    DragBounds inner = dragBounds(kSpotInnerAngleRange);
    inner.max = std::min(inner.max, std::nextafter(light.outerAngleDegrees, -FLT_MAX));
    if (dragNumber("inner angle", light.innerAngleDegrees, 0.25f, inner, "%.2f°"))
        document.markChanged("Spot inner angle");
    helpTooltip("Full intensity inside this angle from the axis.");
    DragBounds outer = dragBounds(kSpotOuterAngleRange);
    outer.min = std::max(outer.min, std::nextafter(light.innerAngleDegrees, FLT_MAX));
    if (dragNumber("outer angle", light.outerAngleDegrees, 0.25f, outer, "%.2f°"))
        document.markChanged("Spot outer angle");
    helpTooltip("No light outside this angle from the axis.");
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
    if (own && dragNumber("shadow softness", light.shadowSoftness, 0.001f,
                          dragBounds(kLightShadowSoftnessRange), "%.3f"))
        document.markChanged("Shadow softness");
}

} // namespace

void drawLightInspector(editor::Document& document, int index, ViewerCommands& commands) {
    Light& light = document.editScene().lights[std::size_t(index)];
    if (ImGui::InputText("name", &light.name)) document.markChanged("Rename");
    drawTypeCombo(light, document);
    if (hasPosition(light.type) &&
        ImGui::DragFloat3("position", &light.position.x,
                          stepFor(std::max(1.0f, glm::length(light.position)))))
        document.markChanged("Light position");
    if (hasDirection(light.type)) drawDirection(light, document);
    if (editColor("colour", light.color)) document.markChanged("Light colour");
    if (dragNumber("intensity", light.intensity, 0.02f, dragBounds(kLightIntensityRange), "%.2f"))
        document.markChanged("Light intensity");
    helpTooltip(light.type == LightType::Directional ? "Illuminance (lux-like)."
                                                     : "Luminous intensity (candela-like).");
    if (hasRange(light.type)) drawRange(light, document);
    if (hasCone(light.type)) drawCone(light, document);
    drawShadows(light, document);
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
