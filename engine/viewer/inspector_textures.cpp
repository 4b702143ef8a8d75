// The inspector's texture files of a material: base colour, normal and roughness, each a file
// name applied when it loads, with its scale, sharpness and (normal maps) strength.
#include "inspector.hpp"

#include "editor/material_texture_edits.hpp"
#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace rmsc::app {

namespace {

// One texture slot: its file field with "apply", why the last apply failed, and the texture's
// scale, sharpness and (normal maps) strength once it has one.
void drawTextureSlot(editor::Document& document, int material, const editor::TextureSlotInfo& slot,
                     TextureFileField& field) {
    ImGui::PushID(slot.key);
    // Refill the text from the scene when another material is shown or the file changed
    // by other means (undo, reload).
    const std::string& file = (document.scene().materials[std::size_t(material)].*slot.member).file;
    if (field.material != material || field.shownFile != file) {
        field.material = material;
        field.shownFile = file;
        field.text = file;
        field.error.clear();
    }
    ImGui::Text("%s", slot.label);
    const bool entered =
        ImGui::InputText("file", &field.text, ImGuiInputTextFlags_EnterReturnsTrue);
    helpTooltip("A PNG or JPEG file, relative to the scene file's folder; empty: no texture. "
                "Enter or apply loads it; a file that does not load changes nothing.");
    ImGui::SameLine();
    if (ImGui::SmallButton("apply") || entered) {
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
    if (!field.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", field.error.c_str());
        ImGui::PopStyleColor();
    }
    MaterialTexture& texture = document.editScene().materials[std::size_t(material)].*slot.member;
    if (texture.present()) {
        bool changed =
            ImGui::DragFloat("scale", &texture.scale, 0.01f, 0.001f, 1e4f, "%.3f",
                             ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
        helpTooltip("Repeats per unit of the shape's own space.");
        changed |= ImGui::DragFloat("sharpness", &texture.sharpness, 0.1f, 1.0f, 64.0f, "%.1f",
                                    ImGuiSliderFlags_AlwaysClamp);
        helpTooltip("How sharply the three projections meet: the exponent of the blend "
                    "weights.");
        if (slot.hasStrength) {
            changed |= ImGui::DragFloat("strength", &texture.strength, 0.01f, 0.0f, 10.0f, "%.2f",
                                        ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("Scales the normal map's bumps (0: flat).");
        }
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
