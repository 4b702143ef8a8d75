// The Scene panel (see hierarchy_panel.hpp). Drags found while drawing are applied once the
// list they belong to is drawn, not mid-traversal.
#include "hierarchy_panel.hpp"

#include "document_edits.hpp"
#include "editor/light_edits.hpp"
#include "editor/multi_selection.hpp"
#include "editor/scene_edits.hpp"
#include "scene/light_spec.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <optional>
#include <string>
#include <vector>

namespace rmsc::app {
namespace {

using editor::Selection;
using editor::SelectionKind;

constexpr const char* kNodePayload = "RMSC_SDF_NODE";
constexpr const char* kMeshPayload = "RMSC_MESH";   // an int: the mesh instance's index
constexpr const char* kLightPayload = "RMSC_LIGHT"; // an int: the light's index

void drawAddButtons(editor::Document& document, const NewShapePlace& place,
                    ViewerCommands& commands) {
    if (ImGui::Button("+ Shape")) ImGui::OpenPopup("add shape");
    if (ImGui::BeginPopup("add shape")) {
        for (const PrimitiveSpec& spec : primitiveCatalogue())
            if (ImGui::Selectable(std::string(spec.name).c_str())) addShape(document, spec, place);
        ImGui::Separator();
        for (const ProfileSolidSpec& solid : profileSolidCatalogue())
            if (ImGui::Selectable(std::string(solid.name).c_str()))
                addProfileShape(document, solid.solid, place);
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("+ Group")) ImGui::OpenPopup("add group");
    if (ImGui::BeginPopup("add group")) {
        for (const OperationSpec& op : operationCatalogue())
            if (ImGui::Selectable(operationLabel(op.op).c_str())) addGroup(document, op.op);
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("+ Light")) ImGui::OpenPopup("add light");
    if (ImGui::BeginPopup("add light")) {
        for (const LightType type : kLightTypes)
            if (ImGui::Selectable(std::string(lightTypeName(type)).c_str(), false,
                                  canAddLight(document) ? 0 : ImGuiSelectableFlags_Disabled))
                commands.push_back(addLightCommand(type));
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("+ Mesh")) commands.push_back(ViewerCommand::AddMesh);
}

// A node dropped onto another: into a group (last), or before a shape.
struct PendingMove {
    std::vector<int> from, into;
    int index = -1;
};

// A node's row: "[operation] name" for groups, "name (solid of profile)" for profile solids
// ("revolution (circle)" while the name is the solid's).
std::string nodeLabel(const SdfNode& node) {
    if (node.isGroup) return "[" + operationLabel(node.op) + "] " + editor::displayName(node);
    std::string label = editor::displayName(node);
    if (!node.profile) return label;
    const std::string solid(profileSolidSpec(node.profile->solid).name);
    const std::string profile(profileSpec(node.profile->type).name);
    return label + (label == solid ? " (" + profile + ")" : " (" + solid + " of " + profile + ")");
}

// Each row's ImGui id is its index among its siblings (pushed) and kNodeId, under its parent's:
// the open state ImGui keeps for a group survives a rename, and rows not drawn can look it up.
constexpr const char* kNodeId = "###node";

// Rows a subtree takes in the panel: its own and, while it is open (groups start open), its
// children's. With this node's index pushed, as drawSdfNode has it.
int subtreeRows(const SdfNode& node) {
    if (!node.isGroup || !ImGui::GetStateStorage()->GetInt(ImGui::GetID(kNodeId), 1)) return 1;
    int rows = 1;
    ImGui::PushID(kNodeId); // as TreeNodeEx pushes it for the children
    for (std::size_t i = 0; i < node.children.size(); ++i) {
        ImGui::PushID(int(i));
        rows += subtreeRows(node.children[i]);
        ImGui::PopID();
    }
    ImGui::PopID();
    return rows;
}

// The rows the panel does not show: only the room they take. A tree of 8,000 nodes took 5.3 ms
// a frame to draw whole (Dear ImGui lays out every row it is given) and takes 1.2 ms.
void skipRows(int rows) {
    if (rows > 0)
        ImGui::Dummy(ImVec2(1.0f, float(rows) * ImGui::GetTextLineHeightWithSpacing() -
                                      ImGui::GetStyle().ItemSpacing.y));
}

void drawSdfNode(const SdfNode& node, std::vector<int>& path, const editor::Document& document,
                 std::optional<Selection>& clicked, std::optional<PendingMove>& move);

// Opens the groups above the node at `path` and returns its row (the root's is 0), with the
// root's id pushed as drawSdfTree has it. nullopt when the path names no node.
std::optional<int> openRowOf(const Scene& scene, const std::vector<int>& path) {
    if (!scene.sdf || !editor::findSdfNode(scene, path)) return std::nullopt;
    const SdfNode* node = &*scene.sdf;
    int row = 0;
    for (const int index : path) {
        ImGui::GetStateStorage()->SetInt(ImGui::GetID(kNodeId), 1);
        ImGui::PushID(kNodeId); // as TreeNodeEx pushes it for the children
        row += 1;               // the group's own row
        for (int i = 0; i < index; ++i) {
            ImGui::PushID(i);
            row += subtreeRows(node->children[std::size_t(i)]);
            ImGui::PopID();
        }
        ImGui::PushID(index);
        node = &node->children[std::size_t(index)];
    }
    for (std::size_t pushed = 0; pushed < 2 * path.size(); ++pushed)
        ImGui::PopID();
    return row;
}

// Scrolls the panel so that the row `row` rows below the cursor, `depth` levels in, is in view:
// to its middle when it is not (a row's height is left below it for the horizontal scrollbar).
void scrollToRow(int row, int depth) {
    const float step = ImGui::GetTextLineHeightWithSpacing();
    const float y = ImGui::GetCursorPosY() + float(row) * step;
    const float height = ImGui::GetWindowHeight();
    if (y < ImGui::GetScrollY() || y + 2.0f * step > ImGui::GetScrollY() + height)
        ImGui::SetScrollY(y - 0.5f * (height - step));
    const float indent = ImGui::GetStyle().IndentSpacing;
    const float x = ImGui::GetCursorPosX() + float(depth) * indent;
    if (x < ImGui::GetScrollX() || x > ImGui::GetScrollX() + 0.5f * ImGui::GetWindowWidth())
        ImGui::SetScrollX(std::max(0.0f, x - 2.0f * indent));
}

// The children of an open group, from `path`: those above or below what the window shows are
// skipped (a non-framed tree node's row is a text line high, so they take the same room).
void drawSdfChildren(const SdfNode& group, std::vector<int>& path, const editor::Document& document,
                     std::optional<Selection>& clicked, std::optional<PendingMove>& move) {
    // (Never while a node is dragged: Dear ImGui ends a drag whose source row is not drawn.)
    const bool all = ImGui::GetDragDropPayload() != nullptr;
    const float top = all ? -FLT_MAX : ImGui::GetWindowDrawList()->GetClipRectMin().y;
    const float bottom = all ? FLT_MAX : ImGui::GetWindowDrawList()->GetClipRectMax().y;
    const float step = ImGui::GetTextLineHeightWithSpacing();
    int above = 0; // rows skipped and not yet given their room
    for (std::size_t i = 0; i < group.children.size(); ++i) {
        const float y = ImGui::GetCursorScreenPos().y + float(above) * step;
        if (y > bottom) { // this one and every later sibling are below the window
            int below = 0;
            for (std::size_t j = i; j < group.children.size(); ++j) {
                ImGui::PushID(int(j));
                below += subtreeRows(group.children[j]);
                ImGui::PopID();
            }
            skipRows(above + below);
            return;
        }
        ImGui::PushID(int(i));
        const int rows = subtreeRows(group.children[i]);
        if (y + float(rows) * step < top) {
            above += rows;
        } else {
            skipRows(above);
            above = 0;
            path.push_back(int(i));
            drawSdfNode(group.children[i], path, document, clicked, move);
            path.pop_back();
        }
        ImGui::PopID();
    }
    skipRows(above);
}

// One node of the SDF tree at `path`, and its children when it is an open group. Its index
// among its siblings is pushed as its id (kNodeId).
void drawSdfNode(const SdfNode& node, std::vector<int>& path, const editor::Document& document,
                 std::optional<Selection>& clicked, std::optional<PendingMove>& move) {
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth |
                               ImGuiTreeNodeFlags_DefaultOpen |
                               ImGuiTreeNodeFlags_OpenOnDoubleClick;
    if (!node.isGroup) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (editor::isSelected(document, Selection::sdf(path))) flags |= ImGuiTreeNodeFlags_Selected;
    const bool open = ImGui::TreeNodeEx(kNodeId, flags, "%s", nodeLabel(node).c_str());
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) clicked = Selection::sdf(path);
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
                move =
                    PendingMove{from, std::vector<int>(path.begin(), path.end() - 1), path.back()};
        }
        ImGui::EndDragDropTarget();
    }
    if (node.isGroup && open) {
        drawSdfChildren(node, path, document, clicked, move);
        ImGui::TreePop();
    }
}

void drawSdfTree(editor::Document& document, HierarchyPanelState& state) {
    std::optional<PendingMove> move;
    std::optional<Selection> clicked;
    const Scene& scene = document.scene();
    ImGui::TextDisabled("SDF objects");
    if (scene.sdf) {
        std::vector<int> path;
        ImGui::PushID(-1); // the root's index
        // A new active selection is brought into view (not while a row is dragged: the drop
        // selects the moved node, in view already).
        if (document.selection != state.revealed && !ImGui::GetDragDropPayload()) {
            state.revealed = document.selection;
            const std::vector<int>& selected = document.selection.sdfPath;
            if (document.selection.kind == SelectionKind::Sdf)
                if (const std::optional<int> row = openRowOf(scene, selected))
                    scrollToRow(*row, int(selected.size()));
        }
        drawSdfNode(*scene.sdf, path, document, clicked, move);
        ImGui::PopID();
    } else {
        ImGui::TextDisabled("  (none: add a shape)");
    }
    if (clicked) editor::clickSelect(document, *clicked, ImGui::GetIO().KeyShift);
    if (move) {
        const PendingMove m = *move;
        document.apply("Reorder", [m](Scene& s, Selection& selection) {
            if (auto to = editor::moveSdfNode(s, m.from, m.into, m.index))
                selection = Selection::sdf(*to);
        });
    }
}

// A mesh or a light dropped onto another of its list.
struct PendingReorder {
    SelectionKind kind = SelectionKind::Mesh;
    int from = -1, to = -1;
};

// One row of the mesh or light list: selects on click, drags onto another row of its list.
void drawListItem(const std::string& name, SelectionKind kind, int index, const char* payloadType,
                  editor::Document& document, std::optional<PendingReorder>& reorder) {
    const Selection itemSelection =
        kind == SelectionKind::Mesh ? Selection::mesh(index) : Selection::light(index);
    const std::string label = name + "##" + payloadType + std::to_string(index);
    if (ImGui::Selectable(label.c_str(), editor::isSelected(document, itemSelection)))
        editor::clickSelect(document, itemSelection, ImGui::GetIO().KeyShift);
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
}

// Meshes and lights: drag one onto another of its list to put it in that place.
void drawMeshAndLightLists(editor::Document& document) {
    std::optional<PendingReorder> reorder;
    const Scene& scene = document.scene();
    ImGui::Spacing();
    ImGui::TextDisabled("Meshes");
    for (std::size_t i = 0; i < scene.meshes.size(); ++i)
        drawListItem(scene.meshes[i].name.empty() ? scene.meshes[i].file : scene.meshes[i].name,
                     SelectionKind::Mesh, int(i), kMeshPayload, document, reorder);
    ImGui::Spacing();
    ImGui::TextDisabled("Lights");
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        drawListItem("[" + std::string(lightTypeName(scene.lights[i].type)) + "] " +
                         editor::lightLabel(scene.lights[i], int(i)),
                     SelectionKind::Light, int(i), kLightPayload, document, reorder);
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
}

void drawHierarchyHelp() {
    ImGui::Spacing();
    ImGui::Separator();
    ImGui::TextDisabled("Drag nodes onto a group to reparent,\nonto a shape to place before it;\n"
                        "drag a mesh or light onto another\nto put it in its place.\n"
                        "Click in the view to select,\nShift+click to add (here too);\n"
                        "G moves, R rotates, S scales\n"
                        "(lights: G moves, R turns)\n"
                        "(X/Y/Z: axis), F frames.\n"
                        "Right mouse + WASD flies;\nAlt + drag orbits.");
}

} // namespace

void drawHierarchyPanel(editor::Document& document, HierarchyPanelState& state,
                        const PanelLayout& layout, const NewShapePlace& place,
                        ViewerCommands& commands) {
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(0, top));
    ImGui::SetNextWindowSize(ImVec2(layout.leftPanelWidth, io.DisplaySize.y - top));
    // A deep tree's rows go past the panel's right edge (tree_4096's leaves are 12 levels in):
    // they scroll into view sideways.
    ImGui::Begin("Scene", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_HorizontalScrollbar);
    drawAddButtons(document, place, commands);
    ImGui::Separator();
    drawSdfTree(document, state);
    drawMeshAndLightLists(document);
    drawHierarchyHelp();
    ImGui::End();
}

} // namespace rmsc::app
