// The inspector's render settings (Render tab): march steps and distance, surface epsilon, the
// environment (background, ambient), exposure, shadows, ambient occlusion and FXAA (see
// inspector.hpp). The shadow and AO fields take the reader's ranges (scene/render_spec.hpp).
#include "inspector.hpp"

#include "editor/param_fields.hpp"
#include "panel_widgets.hpp"
#include "scene/render_spec.hpp"

#include <imgui.h>

namespace rmsc::app {
namespace {

bool dragInt(const char* label, int& value, const ParamRange& range) {
    const editor::IntFieldRange r = editor::intFieldRange(range);
    return ImGui::DragInt(label, &value, 1.0f, r.min, r.max, "%d", ImGuiSliderFlags_AlwaysClamp);
}

bool drawShadows(ShadowSettings& s) {
    bool changed = ImGui::Checkbox("shadows", &s.enabled);
    if (!s.enabled) return changed;
    changed |= dragInt("shadow steps", s.steps, kShadowStepsRange);
    changed |=
        dragFloatInRange("shadow softness", s.softness, 0.001f, kShadowSoftnessRange, "%.3f");
    changed |= dragFloatInRange("shadow min distance", s.minDistance, 0.001f,
                                kShadowMinDistanceRange, "%.4f");
    changed |= dragFloatInRange("shadow max distance", s.maxDistance, 0.5f, kShadowMaxDistanceRange,
                                "%.1f");
    if (!(s.maxDistance > s.minDistance)) s.maxDistance = s.minDistance * 2.0f; // reader's rule
    changed |= dragInt("shadow map size", s.mapSize, kShadowMapSizeRange);
    changed |= dragInt("shadow PCF radius", s.pcfRadius, kShadowPcfRadiusRange);
    changed |= dragFloatInRange("shadow normal offset", s.normalOffset, 0.01f,
                                kShadowNormalOffsetRange, "%.2f");
    changed |=
        dragFloatInRange("shadow slope bias", s.slopeBias, 0.01f, kShadowSlopeBiasRange, "%.2f");
    return changed;
}

bool drawAo(AoSettings& ao) {
    bool changed = dragInt("AO samples", ao.samples, kAoSamplesRange);
    if (ao.samples == 0) return changed;
    changed |= dragFloatInRange("AO distance", ao.distance, 0.005f, kAoDistanceRange, "%.3f");
    changed |= dragFloatInRange("AO strength", ao.strength, 0.01f, kAoStrengthRange, "%.2f");
    return changed;
}

} // namespace

void drawRenderSettingsInspector(editor::Document& document) {
    RenderSettings& r = document.editScene().render;
    bool changed = false;
    changed |=
        ImGui::DragInt("max steps", &r.maxSteps, 1.0f, 1, 4096, "%d", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::DragFloat("max distance", &r.maxDistance, 0.5f, 0.1f, 10000.0f, "%.1f",
                                ImGuiSliderFlags_AlwaysClamp);
    changed |=
        ImGui::DragFloat("surface epsilon", &r.surfaceEpsilon, 0.00005f, 0.000001f, 0.1f, "%.6f",
                         ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
    changed |= editColor("background", r.background);
    changed |= editColor("ambient", r.ambient);
    changed |= ImGui::DragFloat("exposure", &r.exposure, 0.01f, 0.0f, 100.0f, "%.2f",
                                ImGuiSliderFlags_AlwaysClamp);
    changed |= drawShadows(r.shadows);
    changed |= drawAo(r.ao);
    changed |= ImGui::Checkbox("FXAA", &r.fxaa);
    if (changed) document.markChanged("Render settings");
}

} // namespace rmsc::app
