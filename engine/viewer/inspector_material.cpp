// The inspector's material choice and fields (see inspector.hpp).
#include "inspector.hpp"

#include "panel_widgets.hpp"
#include "scene/material_spec.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <string>

namespace rmsc::app {
namespace {

bool editMaterial(Material& m) {
    bool changed = false;
    changed |= editColor("base colour", m.baseColor);
    changed |= numberField("metallic", &m.metallic, 1, 0.01f, kMetallicRange,
                           "0 = dielectric, 1 = metal.", {.format = "%.2f", .slider = true});
    changed |=
        numberField("roughness", &m.roughness, 1, 0.01f, kRoughnessRange,
                    "0 = mirror-smooth, 1 = fully rough.", {.format = "%.2f", .slider = true});
    changed |=
        editColor("emissive", m.emissive, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    return changed;
}

} // namespace

bool chooseMaterial(Scene& scene, int& material, const char* noneLabel) {
    bool changed = false;
    const char* current = material >= 0 && material < int(scene.materials.size())
                              ? scene.materials[std::size_t(material)].name.c_str()
                              : noneLabel;
    if (ImGui::BeginCombo("material", current)) {
        if (ImGui::Selectable(noneLabel, material < 0)) {
            material = -1;
            changed = true;
        }
        for (std::size_t i = 0; i < scene.materials.size(); ++i) {
            const std::string label = scene.materials[i].name + "##m" + std::to_string(i);
            if (ImGui::Selectable(label.c_str(), material == int(i))) {
                material = int(i);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("new")) {
        Material m = material >= 0 && material < int(scene.materials.size())
                         ? scene.materials[std::size_t(material)]
                         : Material{};
        m.name = "material " + std::to_string(scene.materials.size() + 1);
        scene.materials.push_back(m);
        material = int(scene.materials.size()) - 1;
        changed = true;
    }
    if (material >= 0 && material < int(scene.materials.size())) {
        ImGui::Indent();
        Material& m = scene.materials[std::size_t(material)];
        changed |= ImGui::InputText("name##material", &m.name);
        changed |= editMaterial(m);
        ImGui::Unindent();
    }
    return changed;
}

} // namespace rmsc::app
