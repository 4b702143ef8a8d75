// The viewer's Dear ImGui panels: menu bar, hierarchy (with drag and drop), inspector (object,
// material, light, render settings, camera, view), the overlay with timings and messages, and
// the modal dialogs (see viewer.hpp). Widgets edit the document's scene in place and mark it
// changed; the frame loop commits one undo step when no widget is active any more.
#include "editor/recovery.hpp"
#include "viewer/viewer.hpp"

#include "editor/material_texture_edits.hpp"
#include "editor/scene_edits.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/quaternion.hpp>

namespace rmsc::app {
namespace {

using editor::Selection;
using editor::SelectionKind;

std::string pathId(const std::vector<int>& path) {
    std::string id = "r";
    for (int i : path)
        id += "." + std::to_string(i);
    return id;
}

constexpr const char* kNodePayload = "RMSC_SDF_NODE";
constexpr const char* kMeshPayload = "RMSC_MESH";   // an int: the mesh instance's index
constexpr const char* kLightPayload = "RMSC_LIGHT"; // an int: the light's index

// A drag step that follows the size of what is edited (1% of it), never below 0.001.
float stepFor(float size) {
    return std::max(0.001f, std::abs(size) * 0.01f);
}

// Dialogs open in the middle of the window.
void centerNextWindow() {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
}

void helpTooltip(std::string_view text) {
    if (!text.empty() && ImGui::IsItemHovered())
        ImGui::SetTooltip("%.*s", int(text.size()), text.data());
}

} // namespace

void Viewer::drawUi() {
    drawMenuBar();
    drawHierarchy();
    drawInspector();
    drawOverlay();
    drawModals();
}

void Viewer::drawMenuBar() {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("New")) {
            if (document.dirty()) {
                askClose = true;
                afterDiscard = AfterDiscard::New;
            } else {
                newScene();
            }
        }
        if (ImGui::MenuItem("Open...", "Ctrl+O")) {
            askPath = true;
            pathPurpose = PathPurpose::Open;
            pathBuffer = document.file().string();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) save();
        if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) {
            askPath = true;
            pathPurpose = PathPurpose::SaveAs;
            pathBuffer = document.file().empty() ? "scene.json" : document.file().string();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Screenshot", "F12")) screenshotToDefaultFile();
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) {
            afterDiscard = AfterDiscard::Quit;
            requestClose();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const std::string undo = "Undo " + document.undoLabel();
        const std::string redo = "Redo " + document.redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, document.canUndo())) document.undo();
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, document.canRedo()))
            document.redo();
        ImGui::Separator();
        const bool selected = !document.selection.empty();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, selected))
            document.apply("Duplicate", [](Scene& scene, Selection& selection) {
                selection = editor::duplicateSelected(scene, selection);
            });
        if (ImGui::MenuItem("Delete", "Del", false, selected))
            document.apply("Delete", [](Scene& scene, Selection& selection) {
                selection = editor::deleteSelected(scene, selection);
            });
        if (ImGui::MenuItem("Move (grab)", "G, then X/Y/Z", false, false)) {
        }
        if (ImGui::MenuItem("Rotate", "R, then X/Y/Z", false, false)) {
        }
        if (ImGui::MenuItem("Scale", "S, then X/Y/Z", false, false)) {
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Add")) {
        if (ImGui::BeginMenu("Shape")) {
            for (const PrimitiveSpec& spec : primitiveCatalogue()) {
                if (ImGui::MenuItem(std::string(spec.name).c_str()))
                    document.apply("Add " + std::string(spec.name),
                                   [&](Scene& scene, Selection& selection) {
                                       selection = Selection::sdf(editor::insertSdfNode(
                                           scene, selection, editor::makeShape(spec.id)));
                                   });
                helpTooltip(spec.description);
            }
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Group")) {
            for (const OperationSpec& op : operationCatalogue())
                if (ImGui::MenuItem(operationLabel(op.op).c_str()))
                    document.apply("Add group", [&](Scene& scene, Selection& selection) {
                        selection = Selection::sdf(
                            editor::insertSdfNode(scene, selection, editor::makeGroup(op.op)));
                    });
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Directional light"))
            document.apply("Add light", [](Scene& scene, Selection& selection) {
                selection = Selection::light(editor::addLight(scene));
            });
        if (ImGui::MenuItem("glTF mesh from a file...")) {
            askPath = true;
            pathPurpose = PathPurpose::AddMesh;
            pathBuffer.clear();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        const char* names[] = {"Colour", "Normals", "Depth", "Object id", "March steps"};
        for (int i = 0; i < 5; ++i)
            if (ImGui::MenuItem(names[i], nullptr, int(viewMode) == i)) viewMode = ViewMode(i);
        ImGui::Separator();
        ImGui::MenuItem("Overlay", nullptr, &showOverlay);
        ImGui::MenuItem("Adaptive resolution", nullptr, &adaptive.enabled);
        ImGui::SetNextItemWidth(120);
        ImGui::DragFloat("target ms", &adaptive.targetMilliseconds, 0.5f, 5.0f, 500.0f, "%.0f ms");
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Camera")) {
        if (ImGui::MenuItem("Frame selection", "F")) frameSelection();
        if (ImGui::MenuItem("Save camera to scene")) saveCameraToScene();
        if (ImGui::MenuItem("Reset to scene camera")) resetCameraToScene();
        ImGui::EndMenu();
    }
    const std::string title =
        (document.file().empty() ? std::string("(unsaved scene)") : document.file().string()) +
        (document.dirty() ? " *" : "");
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(title.c_str()).x - 16);
    ImGui::TextDisabled("%s", title.c_str());
    ImGui::EndMainMenuBar();
}

void Viewer::drawHierarchy() {
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(0, top));
    ImGui::SetNextWindowSize(ImVec2(leftPanelWidth, io.DisplaySize.y - top));
    ImGui::Begin("Scene", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);

    if (ImGui::Button("+ Shape")) ImGui::OpenPopup("add shape");
    if (ImGui::BeginPopup("add shape")) {
        for (const PrimitiveSpec& spec : primitiveCatalogue())
            if (ImGui::Selectable(std::string(spec.name).c_str()))
                document.apply(
                    "Add " + std::string(spec.name), [&](Scene& scene, Selection& selection) {
                        selection = Selection::sdf(
                            editor::insertSdfNode(scene, selection, editor::makeShape(spec.id)));
                    });
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("+ Group")) ImGui::OpenPopup("add group");
    if (ImGui::BeginPopup("add group")) {
        for (const OperationSpec& op : operationCatalogue())
            if (ImGui::Selectable(operationLabel(op.op).c_str()))
                document.apply("Add group", [&](Scene& scene, Selection& selection) {
                    selection = Selection::sdf(
                        editor::insertSdfNode(scene, selection, editor::makeGroup(op.op)));
                });
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("+ Light"))
        document.apply("Add light", [](Scene& scene, Selection& selection) {
            selection = Selection::light(editor::addLight(scene));
        });
    ImGui::SameLine();
    if (ImGui::Button("+ Mesh")) {
        askPath = true;
        pathPurpose = PathPurpose::AddMesh;
        pathBuffer.clear();
    }
    ImGui::Separator();

    // The SDF tree. Moves found while drawing are applied afterwards, not mid-traversal.
    struct PendingMove {
        std::vector<int> from, into;
        int index = -1;
    };
    std::optional<PendingMove> move;
    const Scene& scene = document.scene();
    std::function<void(const SdfNode&, std::vector<int>&)> drawNode = [&](const SdfNode& node,
                                                                          std::vector<int>& path) {
        ImGuiTreeNodeFlags flags =
            ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth |
            ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_OpenOnDoubleClick;
        if (!node.isGroup) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
        if (document.selection == Selection::sdf(path)) flags |= ImGuiTreeNodeFlags_Selected;
        const std::string label =
            (node.isGroup ? "[" + operationLabel(node.op) + "] " : std::string()) +
            editor::displayName(node) + "##" + pathId(path);
        const bool open = ImGui::TreeNodeEx(label.c_str(), flags);
        if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen())
            document.selection = Selection::sdf(path);
        if (!path.empty() && ImGui::BeginDragDropSource()) {
            ImGui::SetDragDropPayload(kNodePayload, path.data(), path.size() * sizeof(int));
            ImGui::TextUnformatted(editor::displayName(node).c_str());
            ImGui::EndDragDropSource();
        }
        if (ImGui::BeginDragDropTarget()) {
            if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kNodePayload)) {
                const int* data = static_cast<const int*>(payload->Data);
                std::vector<int> from(data, data + payload->DataSize / int(sizeof(int)));
                if (node.isGroup)
                    move = PendingMove{from, path, -1}; // into the group, last
                else
                    move = PendingMove{from, std::vector<int>(path.begin(), path.end() - 1),
                                       path.back()};
            }
            ImGui::EndDragDropTarget();
        }
        if (node.isGroup && open) {
            for (std::size_t i = 0; i < node.children.size(); ++i) {
                path.push_back(int(i));
                drawNode(node.children[i], path);
                path.pop_back();
            }
            ImGui::TreePop();
        }
    };
    ImGui::TextDisabled("SDF objects");
    if (scene.sdf) {
        std::vector<int> path;
        drawNode(*scene.sdf, path);
    } else {
        ImGui::TextDisabled("  (none: add a shape)");
    }
    if (move) {
        const PendingMove m = *move;
        document.apply("Reorder", [m](Scene& s, Selection& selection) {
            if (auto to = editor::moveSdfNode(s, m.from, m.into, m.index))
                selection = Selection::sdf(*to);
        });
    }

    // Meshes and lights: drag one onto another of its list to put it in that place.
    struct PendingReorder {
        SelectionKind kind = SelectionKind::Mesh;
        int from = -1, to = -1;
    };
    std::optional<PendingReorder> reorder;
    const auto listItem = [&](const std::string& name, SelectionKind kind, int index,
                              const char* payloadType) {
        const Selection itemSelection =
            kind == SelectionKind::Mesh ? Selection::mesh(index) : Selection::light(index);
        const std::string label = name + "##" + payloadType + std::to_string(index);
        if (ImGui::Selectable(label.c_str(), document.selection == itemSelection))
            document.selection = itemSelection;
        if (ImGui::BeginDragDropSource()) {
            ImGui::SetDragDropPayload(payloadType, &index, sizeof(index));
            ImGui::TextUnformatted(name.c_str());
            ImGui::EndDragDropSource();
        }
        if (ImGui::BeginDragDropTarget()) {
            if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(payloadType))
                reorder = PendingReorder{kind, *static_cast<const int*>(payload->Data), index};
            ImGui::EndDragDropTarget();
        }
    };
    ImGui::Spacing();
    ImGui::TextDisabled("Meshes");
    for (std::size_t i = 0; i < scene.meshes.size(); ++i)
        listItem(scene.meshes[i].name.empty() ? scene.meshes[i].file : scene.meshes[i].name,
                 SelectionKind::Mesh, int(i), kMeshPayload);
    ImGui::Spacing();
    ImGui::TextDisabled("Lights");
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        listItem(scene.lights[i].name.empty() ? "light " + std::to_string(i + 1)
                                              : scene.lights[i].name,
                 SelectionKind::Light, int(i), kLightPayload);
    if (reorder && reorder->from != reorder->to) {
        const PendingReorder r = *reorder;
        document.apply(r.kind == SelectionKind::Mesh ? "Reorder meshes" : "Reorder lights",
                       [r](Scene& s, Selection& selection) {
                           if (r.kind == SelectionKind::Mesh) {
                               if (const int to = editor::moveMesh(s, r.from, r.to); to >= 0)
                                   selection = Selection::mesh(to);
                           } else if (const int to = editor::moveLight(s, r.from, r.to); to >= 0) {
                               selection = Selection::light(to);
                           }
                       });
    }
    ImGui::Spacing();
    ImGui::Separator();
    ImGui::TextDisabled("Drag nodes onto a group to reparent,\nonto a shape to place before it;\n"
                        "drag a mesh or light onto another\nto put it in its place.\n"
                        "Click in the view to select;\nG moves, R rotates, S scales\n"
                        "(X/Y/Z: axis), F frames.\n"
                        "Right mouse + WASD flies;\nAlt + drag orbits.");
    ImGui::End();
}

namespace {

// Transform widgets; `world` shows the position in world space (through `parentWorld`).
bool editTransform(Transform& t, bool world, const glm::mat4& parentWorld, float size) {
    bool changed = false;
    glm::vec3 position = world ? glm::vec3(parentWorld * glm::vec4(t.position, 1.0f)) : t.position;
    if (ImGui::DragFloat3("position", &position.x, stepFor(size))) {
        t.position =
            world ? glm::vec3(glm::inverse(parentWorld) * glm::vec4(position, 1.0f)) : position;
        changed = true;
    }
    glm::vec3 euler = glm::degrees(glm::eulerAngles(t.rotation));
    if (ImGui::DragFloat3("rotation", &euler.x, 0.5f, -360.0f, 360.0f, "%.1f°")) {
        t.rotation = glm::quat(glm::radians(euler));
        changed = true;
    }
    if (ImGui::DragFloat3("scale", &t.scale.x, 0.005f, 0.001f, 1000.0f, "%.3f",
                          ImGuiSliderFlags_AlwaysClamp))
        changed = true;
    return changed;
}

bool editMaterial(Material& m) {
    bool changed = false;
    changed |= ImGui::ColorEdit3("base colour", &m.baseColor.x, ImGuiColorEditFlags_Float);
    changed |= ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f);
    changed |= ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f);
    changed |= ImGui::ColorEdit3("emissive", &m.emissive.x,
                                 ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    return changed;
}

// Material choice: -1 is "inherit" (SDF) or "the glTF's own" (meshes); returns true on change.
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

// Mesh-shell mode (docs/scene-format.md, "Shells"): on or off, the proxy, a bound the content is
// clipped to, and the proxy's glTF file (applied with Enter, resolved against the scene's
// folder). Returns true when anything changed.
bool editShell(SdfNode& node, const std::filesystem::path& sceneFolder) {
    ImGui::TextDisabled("Shell");
    bool changed = false;
    bool on = node.shell.has_value();
    if (ImGui::Checkbox("draw through a proxy mesh", &on)) {
        if (on) {
            node.shell = SdfShell{};
            node.shell->pointer = node.pointer + "/shell";
        } else {
            node.shell.reset();
        }
        changed = true;
    }
    helpTooltip("Only the pixels the proxy covers march this node; it meets the rest of the scene "
                "through the depth buffer, so every group above it must be a plain union.");
    if (!node.shell) return changed;
    SdfShell& shell = *node.shell;
    static const char* kProxies[] = {"box (the bounds)", "sphere (around the bounds)", "glTF mesh"};
    int proxy = int(shell.proxy);
    if (ImGui::Combo("proxy", &proxy, kProxies, 3)) {
        shell.proxy = ShellProxy(proxy);
        changed = true;
    }
    bool clipped = shell.bound.has_value();
    if (ImGui::Checkbox("clip to a bound", &clipped)) {
        if (clipped) {
            shell.bound = glm::vec3(1.0f);
        } else {
            shell.bound.reset();
        }
        changed = true;
    }
    helpTooltip("Half extents of a box in the node's frame; needed for content that reaches "
                "infinity (planes, unlimited repetition).");
    if (shell.bound)
        changed |= ImGui::DragFloat3("bound", &shell.bound->x, 0.01f, 1e-3f, 1e4f, "%.3f",
                                     ImGuiSliderFlags_AlwaysClamp);
    if (shell.proxy == ShellProxy::Mesh &&
        ImGui::InputText("mesh file", &shell.meshFile, ImGuiInputTextFlags_EnterReturnsTrue)) {
        shell.meshPath = (sceneFolder / shell.meshFile).lexically_normal();
        changed = true;
    }
    return changed;
}

// The node's modifiers, in the order they apply (docs/scene-format.md, "Modifiers"): each with
// the fields of its type and a remove button, then a menu to add one. Lengths drag in steps
// that follow the object's `size`. Returns true when anything changed.
bool editModifiers(SdfNode& node, float size) {
    bool changed = false;
    ImGui::TextDisabled("Modifiers");
    const float step = stepFor(size);
    for (std::size_t i = 0; i < node.modifiers.size(); ++i) {
        SdfModifier& m = node.modifiers[i];
        ImGui::PushID(int(i));
        ImGui::Text("%zu. %s", i + 1, std::string(modifierSpec(m.type).name).c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("remove")) {
            node.modifiers.erase(node.modifiers.begin() + std::ptrdiff_t(i));
            ImGui::PopID();
            return true;
        }
        switch (m.type) {
        case SdfModifierType::Repeat:
            changed |= ImGui::DragFloat3("period", &m.vector.x, step, 0.0f, 1e4f, "%.3f",
                                         ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("Cell size per axis; 0 leaves the axis unrepeated.");
            changed |= ImGui::DragInt3("count", &m.counts.x, 0.1f, 0, 1000, "%d",
                                       ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("Copies per axis; 0 repeats without end.");
            changed |= ImGui::Checkbox("neighbours", &m.neighbours);
            break;
        case SdfModifierType::Mirror:
            changed |= ImGui::Checkbox("x", &m.axes.x);
            ImGui::SameLine();
            changed |= ImGui::Checkbox("y", &m.axes.y);
            ImGui::SameLine();
            changed |= ImGui::Checkbox("z", &m.axes.z);
            break;
        case SdfModifierType::Polar:
            changed |= ImGui::DragInt("copies", &m.count, 0.1f, 1, 1000, "%d",
                                      ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::Combo("axis", &m.axis, "x\0y\0z\0");
            break;
        case SdfModifierType::Elongate:
            changed |= ImGui::DragFloat3("half extents", &m.vector.x, step, 0.0f, 1e4f, "%.3f",
                                         ImGuiSliderFlags_AlwaysClamp);
            break;
        case SdfModifierType::Twist:
        case SdfModifierType::Bend:
            changed |= ImGui::DragFloat("degrees per unit", &m.amount, 0.5f, -3600.0f, 3600.0f,
                                        "%.1f", ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("radius", &m.radius, step, 0.0f, 1e4f, "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("How far from the axis the content reaches (sets the step correction).");
            break;
        case SdfModifierType::Taper: {
            // |amount| x radius stays below 1: the scale must not reach 0 (the reader's check).
            const float most = 0.99f / std::max(m.radius, 1e-4f);
            changed |= ImGui::DragFloat("scale per unit", &m.amount, 0.01f / std::max(size, 1e-3f),
                                        -std::min(most, 100.0f), std::min(most, 100.0f), "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("radius", &m.radius, step, 1e-4f,
                                        std::min(1e4f, 0.99f / std::max(std::abs(m.amount), 1e-4f)),
                                        "%.3f", ImGuiSliderFlags_AlwaysClamp);
            helpTooltip("How far the content reaches: from the y axis, and the height beyond "
                        "which the scale stays constant (sets the step correction).");
            break;
        }
        case SdfModifierType::Round:
            changed |= ImGui::DragFloat("radius", &m.radius, step * 0.25f, 0.0f, 1e4f, "%.4f",
                                        ImGuiSliderFlags_AlwaysClamp);
            break;
        case SdfModifierType::Onion:
            changed |= ImGui::DragFloat("thickness", &m.thickness, step * 0.25f, 1e-4f, 1e4f,
                                        "%.4f", ImGuiSliderFlags_AlwaysClamp);
            break;
        case SdfModifierType::Displace:
            changed |= ImGui::DragFloat("amplitude", &m.amount, step * 0.1f, 0.0f, 1e3f, "%.4f",
                                        ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("frequency", &m.frequency, 0.05f, 1e-3f, 1e3f, "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
            break;
        }
        ImGui::PopID();
    }
    if (ImGui::BeginCombo("add modifier", "...")) {
        for (const ModifierSpec& spec : modifierCatalogue()) {
            if (!ImGui::Selectable(std::string(spec.name).c_str())) continue;
            SdfModifier m;
            m.type = spec.type;
            // Defaults that show the effect at the object's size.
            m.vector = m.type == SdfModifierType::Repeat ? glm::vec3(size * 3.0f, 0.0f, 0.0f)
                                                         : glm::vec3(size * 0.5f, 0.0f, 0.0f);
            m.axes = glm::bvec3(true, false, false);
            m.count = 6;
            m.amount = m.type == SdfModifierType::Displace ? size * 0.05f
                       : m.type == SdfModifierType::Taper  ? 0.5f / std::max(size, 1e-3f)
                                                           : 45.0f;
            m.radius = m.type == SdfModifierType::Round ? size * 0.05f : size;
            m.thickness = size * 0.05f;
            m.frequency = 4.0f / std::max(size, 1e-3f);
            node.modifiers.push_back(m);
            changed = true;
        }
        ImGui::EndCombo();
    }
    return changed;
}

} // namespace

void Viewer::drawInspector() {
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - rightPanelWidth, top));
    ImGui::SetNextWindowSize(ImVec2(rightPanelWidth, io.DisplaySize.y - top));
    ImGui::Begin("Inspector", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-90);
    if (ImGui::BeginTabBar("inspector tabs")) {
        if (ImGui::BeginTabItem("Object")) {
            Scene& scene = document.editScene();
            const Selection selection = document.selection;
            if (selection.kind == SelectionKind::Sdf) {
                SdfNode* node = editor::findSdfNode(scene, selection.sdfPath);
                const std::optional<editor::Bounds> bounds =
                    editor::selectionBounds(scene, selection);
                const float size = bounds ? bounds->radius : 1.0f;
                if (ImGui::InputText("name", &node->name)) document.markChanged("Rename");
                ImGui::Checkbox("world coordinates", &worldCoordinates);
                helpTooltip("Position in world coordinates; R / G with X, Y or Z use the world's "
                            "axes. Off: the position in the parent group and the object's own "
                            "axes.");
                ImGui::Separator();
                ImGui::TextDisabled("Transform");
                if (editTransform(node->transform, worldCoordinates,
                                  editor::sdfParentWorldMatrix(scene, selection.sdfPath), size))
                    document.markChanged("Transform");
                ImGui::Separator();
                if (node->isGroup) {
                    ImGui::TextDisabled("Group");
                    if (ImGui::BeginCombo("operation", operationLabel(node->op).c_str())) {
                        for (const OperationSpec& op : operationCatalogue()) {
                            if (ImGui::Selectable(operationLabel(op.op).c_str(),
                                                  node->op == op.op)) {
                                node->op = op.op;
                                if (takesSmoothness(op.op) && node->smoothness <= 0.0f)
                                    node->smoothness = size * 0.1f;
                                document.markChanged("Operation");
                            }
                        }
                        ImGui::EndCombo();
                    }
                    if (takesSmoothness(node->op) &&
                        ImGui::DragFloat("smoothness", &node->smoothness, stepFor(size) * 0.5f,
                                         0.0f, size * 4.0f, "%.4f", ImGuiSliderFlags_AlwaysClamp))
                        document.markChanged("Smoothness");
                    helpTooltip("Blend distance of the smooth operation, in world units; the drag "
                                "step follows the group's size.");
                } else {
                    ImGui::TextDisabled("Shape");
                    const PrimitiveSpec& spec = primitiveSpec(node->primitive);
                    if (ImGui::BeginCombo("shape", std::string(spec.name).c_str())) {
                        for (const PrimitiveSpec& other : primitiveCatalogue()) {
                            if (ImGui::Selectable(std::string(other.name).c_str(),
                                                  other.id == spec.id) &&
                                other.id != spec.id) {
                                // Parameters of the same name keep their values.
                                PrimitiveParams params = defaultParams(other);
                                for (int i = 0; i < int(other.params.size()); ++i)
                                    for (int j = 0; j < int(spec.params.size()); ++j)
                                        if (other.params[std::size_t(i)].name ==
                                                spec.params[std::size_t(j)].name &&
                                            other.params[std::size_t(i)].components ==
                                                spec.params[std::size_t(j)].components)
                                            for (int c = 0;
                                                 c < other.params[std::size_t(i)].components; ++c)
                                                params[std::size_t(paramOffset(other, i) + c)] =
                                                    node->params[std::size_t(paramOffset(spec, j) +
                                                                             c)];
                                if (node->name == spec.name) node->name = std::string(other.name);
                                node->primitive = other.id;
                                node->params = params;
                                document.markChanged("Shape type");
                            }
                            helpTooltip(other.description);
                        }
                        ImGui::EndCombo();
                    }
                    helpTooltip(spec.description);
                    const PrimitiveSpec& now = primitiveSpec(node->primitive);
                    for (int i = 0; i < int(now.params.size()); ++i) {
                        const ParamSpec& p = now.params[std::size_t(i)];
                        float* value = &node->params[std::size_t(paramOffset(now, i))];
                        const std::string name(p.name);
                        float magnitude = 0.0f;
                        for (int c = 0; c < p.components; ++c)
                            magnitude = std::max(magnitude, std::abs(value[c]));
                        const float step = stepFor(std::max(magnitude, 0.1f));
                        const bool edited = p.components == 3
                                                ? ImGui::DragFloat3(name.c_str(), value, step,
                                                                    p.minValue, p.maxValue, "%.3f",
                                                                    ImGuiSliderFlags_AlwaysClamp)
                                                : ImGui::DragFloat(name.c_str(), value, step,
                                                                   p.minValue, p.maxValue, "%.3f",
                                                                   ImGuiSliderFlags_AlwaysClamp);
                        if (edited) document.markChanged("Edit " + name);
                        helpTooltip(p.description);
                    }
                }
                ImGui::Separator();
                ImGui::TextDisabled("Material");
                if (chooseMaterial(scene, node->material, "(inherit)"))
                    document.markChanged("Material");
                ImGui::Separator();
                if (editModifiers(*node, size)) document.markChanged("Modifiers");
                ImGui::Separator();
                if (editShell(*node, scene.file.parent_path())) document.markChanged("Shell");
                ImGui::Separator();
                drawMaterialTextures(node->material);
                ImGui::Spacing();
                if (ImGui::Button("Duplicate"))
                    document.apply("Duplicate", [](Scene& s, Selection& sel) {
                        sel = editor::duplicateSelected(s, sel);
                    });
                ImGui::SameLine();
                if (ImGui::Button("Delete"))
                    document.apply("Delete", [](Scene& s, Selection& sel) {
                        sel = editor::deleteSelected(s, sel);
                    });
            } else if (selection.kind == SelectionKind::Mesh) {
                MeshInstance& mesh = scene.meshes[std::size_t(selection.index)];
                if (ImGui::InputText("name", &mesh.name)) document.markChanged("Rename");
                ImGui::TextDisabled("file: %s", mesh.file.c_str());
                ImGui::Checkbox("world coordinates", &worldCoordinates);
                helpTooltip("R / G with X, Y or Z: the world's axes when on, the mesh's own "
                            "axes when off.");
                ImGui::Separator();
                const float size = std::max(
                    {mesh.transform.scale.x, mesh.transform.scale.y, mesh.transform.scale.z});
                if (editTransform(mesh.transform, false, glm::mat4(1.0f), size))
                    document.markChanged("Transform");
                ImGui::Separator();
                if (chooseMaterial(scene, mesh.materialOverride, "(glTF materials)"))
                    document.markChanged("Material");
                if (ImGui::Button("Duplicate"))
                    document.apply("Duplicate", [](Scene& s, Selection& sel) {
                        sel = editor::duplicateSelected(s, sel);
                    });
                ImGui::SameLine();
                if (ImGui::Button("Delete"))
                    document.apply("Delete", [](Scene& s, Selection& sel) {
                        sel = editor::deleteSelected(s, sel);
                    });
            } else if (selection.kind == SelectionKind::Light) {
                Light& light = scene.lights[std::size_t(selection.index)];
                if (ImGui::InputText("name", &light.name)) document.markChanged("Rename");
                ImGui::TextDisabled("directional light");
                // Direction as azimuth / elevation: dragging stays on the unit sphere.
                const glm::vec3 d = glm::normalize(light.direction);
                float azimuth = glm::degrees(std::atan2(d.x, d.z));
                float elevation = glm::degrees(std::asin(std::clamp(-d.y, -1.0f, 1.0f)));
                bool changed =
                    ImGui::DragFloat("azimuth", &azimuth, 0.5f, -180.0f, 180.0f, "%.1f°");
                changed |= ImGui::DragFloat("elevation", &elevation, 0.5f, -90.0f, 90.0f, "%.1f°",
                                            ImGuiSliderFlags_AlwaysClamp);
                helpTooltip("Height of the light above the horizon; 90 shines straight down.");
                if (changed) {
                    const float a = glm::radians(azimuth), e = glm::radians(elevation);
                    light.direction = glm::vec3(std::sin(a) * std::cos(e), -std::sin(e),
                                                std::cos(a) * std::cos(e));
                    document.markChanged("Light direction");
                }
                if (ImGui::ColorEdit3("colour", &light.color.x, ImGuiColorEditFlags_Float))
                    document.markChanged("Light colour");
                if (ImGui::DragFloat("intensity", &light.intensity, 0.02f, 0.0f, 1000.0f, "%.2f",
                                     ImGuiSliderFlags_AlwaysClamp))
                    document.markChanged("Light intensity");
                if (ImGui::Button("Duplicate"))
                    document.apply("Duplicate", [](Scene& s, Selection& sel) {
                        sel = editor::duplicateSelected(s, sel);
                    });
                ImGui::SameLine();
                if (ImGui::Button("Delete"))
                    document.apply("Delete", [](Scene& s, Selection& sel) {
                        sel = editor::deleteSelected(s, sel);
                    });
            } else {
                ImGui::TextWrapped("Nothing selected. Click an object in the view or in the Scene "
                                   "panel, or add one with the + buttons.");
            }
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Render")) {
            RenderSettings& r = document.editScene().render;
            bool changed = false;
            changed |= ImGui::DragInt("max steps", &r.maxSteps, 1.0f, 1, 4096, "%d",
                                      ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat("max distance", &r.maxDistance, 0.5f, 0.1f, 10000.0f,
                                        "%.1f", ImGuiSliderFlags_AlwaysClamp);
            changed |= ImGui::DragFloat(
                "surface epsilon", &r.surfaceEpsilon, 0.00005f, 0.000001f, 0.1f, "%.6f",
                ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
            changed |= ImGui::ColorEdit3("background", &r.background.x, ImGuiColorEditFlags_Float);
            changed |= ImGui::ColorEdit3("ambient", &r.ambient.x, ImGuiColorEditFlags_Float);
            changed |= ImGui::DragFloat("exposure", &r.exposure, 0.01f, 0.0f, 100.0f, "%.2f",
                                        ImGuiSliderFlags_AlwaysClamp);
            if (changed) document.markChanged("Render settings");
            ImGui::Separator();
            ImGui::TextDisabled("Camera");
            Camera& c = document.editScene().camera;
            bool cameraChanged = ImGui::DragFloat("fov", &c.fovYDegrees, 0.2f, 1.0f, 170.0f,
                                                  "%.1f°", ImGuiSliderFlags_AlwaysClamp);
            cameraChanged |=
                ImGui::DragFloat("near", &c.nearPlane, 0.001f, 0.0001f, c.farPlane * 0.5f, "%.4f",
                                 ImGuiSliderFlags_AlwaysClamp);
            cameraChanged |= ImGui::DragFloat("far", &c.farPlane, 0.5f, c.nearPlane * 2.0f,
                                              100000.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
            if (cameraChanged) {
                sceneCameraBase.fovYDegrees = c.fovYDegrees;
                sceneCameraBase.nearPlane = c.nearPlane;
                sceneCameraBase.farPlane = c.farPlane;
                document.markChanged("Camera lens");
            }
            if (ImGui::Button("Save camera to scene")) saveCameraToScene();
            ImGui::SameLine();
            if (ImGui::Button("Reset to scene camera")) resetCameraToScene();
            ImGui::DragFloat("fly speed", &camera.speed, 0.05f, 0.01f, 1000.0f, "%.2f m/s");
            ImGui::Separator();
            ImGui::TextDisabled("View");
            const char* names[] = {"colour", "normals", "depth", "object id", "march steps"};
            int mode = int(viewMode);
            if (ImGui::Combo("show", &mode, names, 5)) viewMode = ViewMode(mode);
            ImGui::Checkbox("adaptive resolution", &adaptive.enabled);
            ImGui::DragFloat("target", &adaptive.targetMilliseconds, 0.5f, 5.0f, 500.0f,
                             "%.0f ms/frame");
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

void Viewer::drawMaterialTextures(int material) {
    ImGui::TextDisabled("Material textures");
    if (material < 0 || material >= int(document.scene().materials.size())) {
        ImGui::TextWrapped("The shape inherits its material: choose or create one above to give "
                           "it textures.");
        return;
    }
    helpTooltip("Images mapped onto the shape by triplanar projection in its own space.");
    for (const editor::TextureSlotInfo& slot : editor::textureSlots()) {
        TextureFileField& field = textureFileFields[std::size_t(slot.slot)];
        ImGui::PushID(slot.key);
        // Refill the text from the scene when another material is shown or the file changed
        // by other means (undo, reload).
        const std::string& file =
            (document.scene().materials[std::size_t(material)].*slot.member).file;
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
                               [&](Scene& scene, Selection&) { scene = std::move(candidate); });
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
        MaterialTexture& texture =
            document.editScene().materials[std::size_t(material)].*slot.member;
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
                changed |= ImGui::DragFloat("strength", &texture.strength, 0.01f, 0.0f, 10.0f,
                                            "%.2f", ImGuiSliderFlags_AlwaysClamp);
                helpTooltip("Scales the normal map's bumps (0: flat).");
            }
            if (changed) document.markChanged("Texture " + std::string(slot.label));
        }
        ImGui::PopID();
    }
}

void Viewer::drawOverlay() {
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (showOverlay) {
        ImGui::SetNextWindowPos(ImVec2(viewport.x + 8, viewport.y + 8));
        ImGui::SetNextWindowBgAlpha(0.55f);
        ImGui::Begin("overlay", nullptr, fixed | ImGuiWindowFlags_NoInputs);
        const int w = targets ? targets->display.width : 0,
                  h = targets ? targets->display.height : 0;
        ImGui::Text("frame %.1f ms   render %.1f ms", frameMilliseconds, lastRenderMilliseconds);
        ImGui::Text("render scale %.0f%% (%dx%d)%s", lastRenderScale * 100.0f, w, h,
                    adaptive.enabled ? "" : "  adaptive off");
        const std::string_view map = editor::editingMapName(drawnMap);
        ImGui::Text("SDF map: %.*s%s%s", int(map.size()), map.data(),
                    drawnMap == editor::EditingMapKind::Baked && choiceLive.first <= choiceLive.last
                        ? ", selection live"
                        : "",
                    sceneChanged ? " (the newest scene shows once its shaders are built)"
                    : warmer && !warmer->idle() ? " (building better ones)"
                                                : "");
        const char* names[] = {"colour", "normals", "depth", "object id"};
        ImGui::Text("view: %s   speed %.2f m/s", names[int(viewMode)], camera.speed);
        if (gesture.active) {
            const editor::TransformGesture& g = gesture.math;
            const char* what = g.kind == editor::GestureKind::Move     ? "Move"
                               : g.kind == editor::GestureKind::Rotate ? "Rotate"
                                                                       : "Scale";
            const char* free = g.kind == editor::GestureKind::Move     ? "in the view plane"
                               : g.kind == editor::GestureKind::Rotate ? "about the view axis"
                                                                       : "uniformly";
            std::string axis = free;
            if (g.axis >= 0) {
                // Scaling always uses the object's own axes (a world axis would need shear).
                const bool world =
                    g.space == editor::AxisSpace::World && g.kind != editor::GestureKind::Scale;
                axis = std::string(g.kind == editor::GestureKind::Rotate ? "about " : "along ") +
                       char('X' + g.axis) + (world ? " (world)" : " (own axis)");
            }
            ImGui::TextColored(ImVec4(1, 0.7f, 0.2f, 1),
                               "%s %s: mouse drives it, X/Y/Z axis, click/Enter keeps, Esc cancels",
                               what, axis.c_str());
        }
        const double t = now();
        for (const auto& [text, when] : notices)
            if (t - when < 4.0) ImGui::TextColored(ImVec4(0.6f, 0.9f, 0.6f, 1), "%s", text.c_str());
        ImGui::End();
    }
    std::string errors;
    for (const std::string* e : {&openError, &sceneError, &shaderError, &fileError})
        if (!e->empty()) errors += (errors.empty() ? "" : "\n") + *e;
    if (!errors.empty()) {
        ImGui::SetNextWindowPos(ImVec2(viewport.x + 8, viewport.y + viewport.height - 8), 0,
                                ImVec2(0, 1));
        ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                            ImVec2(viewport.width - 16, viewport.height * 0.5f));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("problems", nullptr, fixed & ~ImGuiWindowFlags_NoDecoration);
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::PushTextWrapPos(viewport.width - 40);
        ImGui::TextUnformatted(errors.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
        if (ImGui::SmallButton("dismiss")) {
            openError.clear();
            fileError.clear();
        }
        ImGui::End();
    }
}

void Viewer::drawModals() {
    if (askRecover) {
        ImGui::OpenPopup("Recover unsaved edits");
        askRecover = false;
    }
    centerNextWindow();
    if (ImGui::BeginPopupModal("Recover unsaved edits", nullptr,
                               ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("Edits that were never saved were found in\n%s",
                    offeredRecovery ? offeredRecovery->string().c_str() : "");
        if (ImGui::Button("Recover")) {
            Diagnostics diagnostics;
            std::optional<Scene> recovered =
                offeredRecovery ? editor::loadSceneForEditing(*offeredRecovery, diagnostics)
                                : std::nullopt;
            if (recovered) {
                recovered->file = document.scene().file;
                document.apply("Recover unsaved edits",
                               [&](Scene& scene, editor::Selection&) { scene = *recovered; });
                notice("recovered the unsaved edits; save to keep them");
            } else {
                fileError = "The recovery file does not load:\n" + diagnostics.format();
            }
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard them")) {
            editor::removeRecovery(document.file());
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }

    if (askClose) {
        ImGui::OpenPopup("Unsaved changes");
        askClose = false;
    }
    centerNextWindow();
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("The scene has unsaved changes.");
        if (ImGui::Button("Save")) {
            save();
            if (!document.dirty()) {
                if (afterDiscard == AfterDiscard::Quit)
                    quitNow = true;
                else
                    newScene();
            }
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard changes")) {
            editor::removeRecovery(document.file());
            if (afterDiscard == AfterDiscard::Quit)
                quitNow = true;
            else
                newScene();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (askPath) {
        ImGui::OpenPopup("File");
        askPath = false;
    }
    centerNextWindow();
    if (ImGui::BeginPopupModal("File", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const char* what = pathPurpose == PathPurpose::Open     ? "Open scene file (.json):"
                           : pathPurpose == PathPurpose::SaveAs ? "Save scene as (.json):"
                                                                : "Add a glTF mesh (.gltf / .glb):";
        ImGui::TextUnformatted(what);
        if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
        ImGui::SetNextItemWidth(420);
        const bool entered =
            ImGui::InputText("##path", &pathBuffer, ImGuiInputTextFlags_EnterReturnsTrue);
        if ((ImGui::Button("OK") || entered) && !pathBuffer.empty()) {
            const std::filesystem::path path = pathBuffer;
            if (pathPurpose == PathPurpose::Open) {
                openFile(path);
            } else if (pathPurpose == PathPurpose::SaveAs) {
                saveAs(path);
            } else {
                std::error_code ec;
                if (!std::filesystem::exists(path, ec)) {
                    fileError = path.string() + ": no such file";
                } else {
                    document.apply("Add mesh", [&](Scene& scene, Selection& selection) {
                        const int index = editor::addMesh(scene, std::filesystem::absolute(path));
                        selection = Selection::mesh(index);
                    });
                }
            }
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (externalChangePending) {
        ImGui::OpenPopup("Changed on disk");
        externalChangePending = false;
    }
    centerNextWindow();
    if (ImGui::BeginPopupModal("Changed on disk", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s changed on disk, and you have unsaved edits.",
                    document.file().string().c_str());
        if (ImGui::Button("Reload (lose my edits)")) {
            Diagnostics diagnostics;
            if (std::optional<Scene> scene =
                    editor::loadSceneForEditing(document.file(), diagnostics))
                document.reloadFromDisk(*scene);
            else
                sceneError = diagnostics.format();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Keep my edits")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

} // namespace rmsc::app
