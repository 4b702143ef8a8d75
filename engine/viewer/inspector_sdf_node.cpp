// The inspector for an SDF node: name, transform, the group's operation or the shape's type and
// parameters (with the catalogue's ranges), material, modifiers, shell and material textures
// (see inspector.hpp).
#include "inspector.hpp"

#include "editor/inspector_keys.hpp"
#include "editor/param_fields.hpp"
#include "editor/profile_edits.hpp"
#include "editor/scene_edits.hpp"
#include "panel_widgets.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace rmsc::app {
namespace {

// A group's operation and, for the smooth ones, its smoothness; `size` is the group's.
void drawGroupFields(SdfNode& node, float size, editor::Document& document) {
    ImGui::TextDisabled("Group");
    if (ImGui::BeginCombo("operation", operationLabel(node.op).c_str())) {
        for (const OperationSpec& op : operationCatalogue()) {
            if (ImGui::Selectable(operationLabel(op.op).c_str(), node.op == op.op)) {
                node.op = op.op;
                const editor::FloatFieldRange range = editor::smoothnessFieldRange();
                if (takesSmoothness(op.op) && node.smoothness <= 0.0f)
                    node.smoothness = std::clamp(size * 0.1f, range.min, range.max);
                document.markChanged("Operation");
            }
        }
        ImGui::EndCombo();
    }
    if (takesSmoothness(node.op) &&
        numberField("smoothness", &node.smoothness, 1, stepFor(size) * 0.5f,
                    smoothnessParam().range, smoothnessParam().description, {.format = "%.4f"}))
        document.markChanged("Smoothness");
    if (!takesBlend(node.op)) return;
    const std::span<const BlendSpec> blends = blendCatalogue();
    const auto current = std::find_if(blends.begin(), blends.end(),
                                      [&](const BlendSpec& b) { return b.blend == node.blend; });
    const std::string currentName =
        current != blends.end() ? std::string(current->name) : std::string("?");
    if (ImGui::BeginCombo(editor::kBlendControl, currentName.c_str())) {
        for (const BlendSpec& blend : blends) {
            if (ImGui::Selectable(std::string(blend.name).c_str(), node.blend == blend.blend) &&
                node.blend != blend.blend) {
                node.blend = blend.blend;
                document.markChanged("Blend");
            }
            helpTooltip(blend.description);
        }
        ImGui::EndCombo();
    }
    helpTooltip("The curve of the smooth seam.");
}

// Makes the shape `other`; parameters of the same name keep their values.
void changeShape(SdfNode& node, const PrimitiveSpec& spec, const PrimitiveSpec& other) {
    PrimitiveParams params = defaultParams(other);
    for (int i = 0; i < int(other.params.size()); ++i)
        for (int j = 0; j < int(spec.params.size()); ++j)
            if (other.params[std::size_t(i)].name == spec.params[std::size_t(j)].name &&
                other.params[std::size_t(i)].components == spec.params[std::size_t(j)].components)
                for (int c = 0; c < other.params[std::size_t(i)].components; ++c)
                    params[std::size_t(paramOffset(other, i) + c)] =
                        node.params[std::size_t(paramOffset(spec, j) + c)];
    if (node.name == spec.name) node.name = std::string(other.name);
    node.primitive = other.id;
    node.params = params;
}

// Makes the node the profile solid `solid`: a profile it has keeps its values, a name that was
// its shape's becomes the solid's.
void changeToSolid(SdfNode& node, SdfProfileSolid solid) {
    const std::string shapeName = node.profile ? editor::profileShapeName(*node.profile)
                                               : std::string(primitiveSpec(node.primitive).name);
    SdfNode made = editor::makeProfileShape(solid);
    if (node.profile) {
        made.profile = *node.profile;
        made.profile->solid = solid;
    }
    node.profile = made.profile;
    if (node.name == shapeName) node.name = made.name;
}

// The shape's type (every primitive of the catalogue and every profile solid) and its
// parameters, or its profile.
void drawShapeFields(SdfNode& node, editor::Document& document, float size) {
    ImGui::TextDisabled("Shape");
    const PrimitiveSpec& spec = primitiveSpec(node.primitive);
    const std::string current =
        node.profile ? editor::profileShapeName(*node.profile) : std::string(spec.name);
    if (ImGui::BeginCombo("shape", current.c_str())) {
        for (const PrimitiveSpec& other : primitiveCatalogue()) {
            const bool isCurrent = !node.profile && other.id == spec.id;
            if (ImGui::Selectable(std::string(other.name).c_str(), isCurrent) && !isCurrent) {
                if (node.profile) {
                    if (node.name == editor::profileShapeName(*node.profile))
                        node.name = std::string(spec.name);
                    node.profile.reset();
                }
                changeShape(node, spec, other);
                document.markChanged("Shape type");
            }
            helpTooltip(other.description);
        }
        ImGui::Separator();
        for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
            const bool isCurrent = node.profile && node.profile->solid == solid.solid;
            if (ImGui::Selectable(std::string(solid.name).c_str(), isCurrent) && !isCurrent) {
                changeToSolid(node, solid.solid);
                document.markChanged("Shape type");
            }
            helpTooltip(solid.description);
        }
        ImGui::EndCombo();
    }
    if (node.profile) {
        helpTooltip(profileSolidSpec(node.profile->solid).description);
        if (editProfile(*node.profile, size)) document.markChanged("Edit profile");
        return;
    }
    helpTooltip(spec.description);
    const PrimitiveSpec& now = primitiveSpec(node.primitive);
    for (int i = 0; i < int(now.params.size()); ++i) {
        const ParamSpec& p = now.params[std::size_t(i)];
        float* value = &node.params[std::size_t(paramOffset(now, i))];
        const std::string name(p.name);
        float magnitude = 0.0f;
        for (int c = 0; c < p.components; ++c)
            magnitude = std::max(magnitude, std::abs(value[c]));
        const float step = stepFor(std::max(magnitude, 0.1f));
        if (numberField(name.c_str(), value, p.components, step, editor::primitiveParamRange(p),
                        p.description))
            document.markChanged("Edit " + name);
    }
}

} // namespace

void drawSdfNodeInspector(editor::Document& document, const std::vector<int>& path,
                          InspectorState& state, ViewerCommands& commands) {
    Scene& scene = document.editScene();
    SdfNode* node = editor::findSdfNode(scene, path);
    const std::optional<editor::Bounds> bounds =
        editor::selectionBounds(scene, editor::Selection::sdf(path));
    const float size = bounds ? bounds->radius : 1.0f;
    if (ImGui::InputText("name", &node->name)) document.markChanged("Rename");
    ImGui::Checkbox("world coordinates", &state.worldCoordinates);
    helpTooltip("Position in world coordinates; R / G with X, Y or Z use the world's "
                "axes. Off: the position in the parent group and the object's own "
                "axes.");
    ImGui::Separator();
    ImGui::TextDisabled("Transform");
    if (editTransform(node->transform, state.worldCoordinates,
                      editor::sdfParentWorldMatrix(scene, path), size))
        document.markChanged("Transform");
    if (!path.empty()) {
        if (ImGui::Checkbox(editor::kCutControl, &node->cut)) document.markChanged("Cut");
        helpTooltip("Subtracted from the union (or other operation) of its siblings that are not "
                    "cut, whichever order they come in. A group needs at least one child that is "
                    "not cut.");
    }
    ImGui::Separator();
    if (node->isGroup)
        drawGroupFields(*node, size, document);
    else
        drawShapeFields(*node, document, size);
    ImGui::Separator();
    ImGui::TextDisabled("Material");
    if (chooseMaterial(scene, node->material, "(inherit)")) document.markChanged("Material");
    ImGui::Separator();
    if (editModifiers(*node, size, state.modifierRefusal)) document.markChanged("Modifiers");
    ImGui::Separator();
    if (editShell(*node, scene.file.parent_path())) document.markChanged("Shell");
    ImGui::Separator();
    drawMaterialTextures(document, node->material, state.textureFiles);
    ImGui::Spacing();
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
