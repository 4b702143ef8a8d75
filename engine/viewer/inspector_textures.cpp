// The inspector's texture files of a material: base colour, normal and roughness, each a file
// name applied when it loads, with its scale, sharpness and (normal maps) strength.
#include "inspector.hpp"

#include "editor/material_texture_edits.hpp"
#include "panel_widgets.hpp"
#include "scene/material_spec.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace rmsc::app {

namespace {

// One texture slot: its file field with "apply", why the last apply failed, and the texture's
// scale, sharpness and (normal maps) strength once it has one.
void drawTextureSlot(editor::Document& document, int material, const editor::TextureSlotInfo& slot,
                     FileField& field) {
    ImGui::PushID(slot.key);
    const std::string& file = (document.scene().materials[std::size_t(material)].*slot.member).file;
    ImGui::Text("%s", slot.label);
    if (drawFileField("file", field, material, file,
                      "A PNG or JPEG file, relative to the scene file's folder; empty: no "
                      "texture. Enter or apply loads it; a file that does not load changes "
                      "nothing.",
                      editor::FileKind::Texture)) {
        Scene candidate = document.scene();
        std::string error;
        if (editor::setMaterialTextureFile(candidate, material, slot.slot, field.text,
                                           diskFileSource(), error)) {
            document.apply(field.text.empty() ? "Remove texture" : "Texture file",
                           [&](Scene& scene, editor::Selection&) { scene = std::move(candidate); });
            field.error.clear();
        } else {
            field.error = error;
        }
    }
    drawRefusal(field.error);
    MaterialTexture& texture = document.editScene().materials[std::size_t(material)].*slot.member;
    if (texture.present()) {
        bool changed = numberField(
            "scale", &texture.scale, 1, 0.01f, kTextureScaleRange,
            "Repeats per unit of the shape's own space.",
            {.flags = ImGuiSliderFlags_Logarithmic, .drag = editor::FloatFieldRange{0.001f, 1e4f}});
        changed |= numberField("sharpness", &texture.sharpness, 1, 0.1f, kTextureSharpnessRange,
                               "How sharply the three projections meet: the exponent of the "
                               "blend weights.",
                               {.format = "%.1f"});
        if (slot.hasStrength)
            changed |= numberField("strength", &texture.strength, 1, 0.01f, kNormalStrengthRange,
                                   "Scales the normal map's bumps (0: flat).", {.format = "%.2f"});
        if (changed) document.markChanged("Texture " + std::string(slot.label));
    }
    ImGui::PopID();
}

} // namespace

void drawMaterialTextures(editor::Document& document, int material, TextureFileFields& fields) {
    ImGui::TextDisabled("Material textures");
    if (material < 0 || material >= int(document.scene().materials.size())) {
        ImGui::TextWrapped("The shape inherits its material: choose or create one above to give "
                           "it textures.");
        return;
    }
    helpTooltip("Images mapped onto the shape by triplanar projection in its own space.");
    for (const editor::TextureSlotInfo& slot : editor::textureSlots())
        drawTextureSlot(document, material, slot, fields[std::size_t(slot.slot)]);
}

} // namespace rmsc::app
