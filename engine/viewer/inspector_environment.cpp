// The inspector's environment (Render tab): the sky's type, its colours, an image sky's file
// and rotation, its intensity, and the fog (see inspector.hpp). Number fields take the reader's
// ranges (scene/environment_spec.hpp); the sky image is set only once it has loaded
// (editor/environment_edits.hpp).
#include "inspector.hpp"

#include "editor/environment_edits.hpp"
#include "editor/param_fields.hpp"
#include "panel_widgets.hpp"
#include "scene/environment_spec.hpp"

#include <imgui.h>

namespace rmsc::app {
namespace {

// The sky type combo; an image sky without a file is refused (then the file field shows).
void chooseSkyType(editor::Document& document, EnvironmentFields& fields) {
    const char* names[] = {"none", "constant", "gradient", "image"};
    static_assert(int(SkyType::Image) == 3 && kSkyTypeNames.size() == 3);
    Environment& environment = document.editScene().environment;
    int type = int(environment.sky);
    if (!ImGui::Combo("sky", &type, names, 4) || SkyType(type) == environment.sky) return;
    std::string error;
    if (editor::setSkyType(environment, SkyType(type), error)) {
        fields.skyRefusal.clear();
        fields.choosingImage = false;
        document.markChanged("Sky type");
    } else {
        fields.skyRefusal = error;
        fields.choosingImage = true;
    }
}

// The image sky's file (applied when it loads) and rotation.
void drawSkyImage(editor::Document& document, EnvironmentFields& fields) {
    const Environment& shown = document.scene().environment;
    if (drawFileField("file", fields.skyFile, 0, shown.imageFile,
                      "An equirectangular image (Radiance .hdr; PNG and JPEG are read as sRGB), "
                      "relative to the scene file's folder. Enter or apply loads it; a file that "
                      "does not load changes nothing.",
                      editor::FileKind::Sky)) {
        Scene candidate = document.scene();
        std::string error;
        if (editor::setSkyImageFile(candidate, fields.skyFile.text, diskFileSource(), error)) {
            document.apply("Sky image",
                           [&](Scene& scene, editor::Selection&) { scene = std::move(candidate); });
            fields.skyFile.error.clear();
            fields.skyRefusal.clear();
            fields.choosingImage = false;
        } else {
            fields.skyFile.error = error;
        }
    }
    drawRefusal(fields.skyFile.error);
}

} // namespace

void drawEnvironmentInspector(editor::Document& document, EnvironmentFields& fields) {
    ImGui::TextDisabled("Environment");
    ImGui::PushID("environment"); // labels such as "colour" and "file" are the sky's here
    chooseSkyType(document, fields);
    helpTooltip("What rays that hit nothing see, and the light every surface gets from around "
                "it. None: the background colour behind, the ambient colour as light.");
    drawRefusal(fields.skyRefusal);
    // A reference into the scene, which an applied sky image replaces as a whole (the
    // reference stays valid: the scene object is assigned, not moved).
    Environment& env = document.editScene().environment;
    bool changed = false;
    switch (env.sky) {
    case SkyType::None:
        break;
    case SkyType::Constant:
        changed |= editColor("colour", env.color);
        break;
    case SkyType::Gradient:
        changed |= editColor("zenith", env.zenith);
        changed |= editColor("horizon", env.horizon);
        changed |= editColor("ground", env.ground);
        break;
    case SkyType::Image:
        break;
    }
    if (env.sky == SkyType::Image || fields.choosingImage) drawSkyImage(document, fields);
    if (env.sky == SkyType::Image) {
        changed |= numberField("rotation", &env.rotationDegrees, 1, 0.5f, kSkyRotationRange,
                               "Turns the image about +Y.", {.format = "%.1f°"});
    }
    if (env.sky != SkyType::None) {
        changed |=
            numberField("intensity", &env.intensity, 1, 0.01f, kEnvironmentIntensityRange,
                        "Multiplies the sky, as background and as light.", {.format = "%.2f"});
    }
    bool fog = env.fogDensity > 0.0f;
    if (ImGui::Checkbox("fog", &fog)) {
        env.fogDensity = fog ? 0.05f : 0.0f;
        changed = true;
    }
    helpTooltip("Exponential fog: a surface d metres away keeps exp(-density d) of its colour, "
                "the rest is the fog colour. The sky is not fogged.");
    if (fog) {
        changed |= numberField("density", &env.fogDensity, 1, 0.001f, kFogDensityRange,
                               "How thick the fog is: a surface d metres away keeps "
                               "exp(-density d) of its colour.",
                               {.format = "%.3f"});
        changed |= editColor("fog colour", env.fogColor);
    }
    ImGui::PopID();
    if (changed) document.markChanged("Environment");
}

} // namespace rmsc::app
