// The inspector's render settings (Render tab): march steps and distance, surface epsilon, the
// environment (background, ambient), exposure, shadows, ambient occlusion and FXAA (see
// inspector.hpp). Every number field takes the reader's range and unit (scene/render_spec.hpp).
#include "inspector.hpp"

#include "editor/param_fields.hpp"
#include "panel_widgets.hpp"
#include "scene/render_spec.hpp"

#include <imgui.h>

namespace rmsc::app {
namespace {

bool drawShadows(ShadowSettings& s) {
    bool changed = ImGui::Checkbox("shadows", &s.enabled);
    if (!s.enabled) return changed;
    changed |= numberField("shadow steps", &s.steps, 1, 1.0f, kShadowStepsRange,
                           "SDF shadow-march steps per light and pixel.");
    changed |= numberField("shadow softness", &s.softness, 1, 0.001f, kShadowSoftnessRange,
                           "Penumbra width factor w of the SDF shadows (Quilez's k = 1 / w); a "
                           "light's own softness overrides it.");
    changed |=
        numberField("shadow min distance", &s.minDistance, 1, 0.001f, kShadowMinDistanceRange,
                    "The shadow march starts this far from the surface.", {.format = "%.4f"});
    changed |= numberField("shadow max distance", &s.maxDistance, 1, 0.5f, kShadowMaxDistanceRange,
                           "The shadow march gives up after this distance.", {.format = "%.1f"});
    if (!(s.maxDistance > s.minDistance)) s.maxDistance = s.minDistance * 2.0f; // reader's rule
    changed |= numberField("shadow map size", &s.mapSize, 1, 1.0f, kShadowMapSizeRange,
                           "Shadow-map texels a side (meshes' shadows).");
    changed |= numberField("shadow PCF radius", &s.pcfRadius, 1, 1.0f, kShadowPcfRadiusRange,
                           "PCF kernel radius in shadow-map texels.");
    changed |=
        numberField("shadow normal offset", &s.normalOffset, 1, 0.01f, kShadowNormalOffsetRange,
                    "Shadow-map lookups move this many texels along the normal (against "
                    "acne).",
                    {.format = "%.2f"});
    changed |= numberField("shadow slope bias", &s.slopeBias, 1, 0.01f, kShadowSlopeBiasRange,
                           "Slope-scaled depth bias of the shadow-map pass (polygon offset "
                           "factor).",
                           {.format = "%.2f"});
    return changed;
}

bool drawAo(AoSettings& ao) {
    bool changed = numberField("AO samples", &ao.samples, 1, 1.0f, kAoSamplesRange,
                               "Ambient occlusion samples along the normal; 0 turns AO off.");
    if (ao.samples == 0) return changed;
    changed |= numberField("AO distance", &ao.distance, 1, 0.005f, kAoDistanceRange,
                           "Height of the farthest sample.");
    changed |= numberField("AO strength", &ao.strength, 1, 0.01f, kAoStrengthRange,
                           "0 = no darkening.", {.format = "%.2f"});
    return changed;
}

} // namespace

void drawRenderSettingsInspector(editor::Document& document) {
    RenderSettings& r = document.editScene().render;
    bool changed = false;
    changed |= numberField("max steps", &r.maxSteps, 1, 1.0f, kMaxStepsRange,
                           "Each ray stops after this many sphere-tracing steps.");
    changed |= numberField("max distance", &r.maxDistance, 1, 0.5f, kMaxDistanceRange,
                           "Rays stop after this distance.",
                           {.format = "%.1f", .drag = editor::FloatFieldRange{0.1f, 1e4f}});
    changed |= numberField("surface epsilon", &r.surfaceEpsilon, 1, 0.00005f, kSurfaceEpsilonRange,
                           "A ray hits a surface when the distance falls below this times the "
                           "distance travelled.",
                           {.format = "%.6f",
                            .flags = ImGuiSliderFlags_Logarithmic,
                            .drag = editor::FloatFieldRange{0.000001f, 0.1f}});
    changed |= editColor("background", r.background);
    changed |= editColor("ambient", r.ambient);
    changed |= numberField("exposure", &r.exposure, 1, 0.01f, kExposureRange,
                           "Multiplies the HDR colour before tone mapping.",
                           {.format = "%.2f", .drag = editor::FloatFieldRange{0.001f, 100.0f}});
    changed |= drawShadows(r.shadows);
    changed |= drawAo(r.ao);
    changed |= ImGui::Checkbox("FXAA", &r.fxaa);
    if (changed) document.markChanged("Render settings");
}

} // namespace rmsc::app
