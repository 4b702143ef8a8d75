// The inspector for a mesh instance: name, its glTF file (taken only when it loads,
// editor/mesh_file_edits.hpp), transform, material override, then what its glTF file holds
// (inspector_mesh_gltf.cpp; see inspector.hpp).
#include "inspector.hpp"

#include "editor/mesh_file_edits.hpp"
#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace rmsc::app {

void drawMeshInspector(EditorSession& session, int index, InspectorState& state,
                       ViewerCommands& commands) {
    editor::Document& document = session.document;
    if (ImGui::InputText("name", &document.editScene().meshes[std::size_t(index)].name))
        document.markChanged("Rename");
    FileField& field = state.meshFile;
    if (drawFileField("file", field, index, document.scene().meshes[std::size_t(index)].file,
                      "A .gltf or .glb file, relative to the scene file's folder. Enter or apply "
                      "loads it; a file that does not load changes nothing.",
                      editor::FileKind::Mesh)) {
        Scene candidate = document.scene();
        std::string error;
        if (editor::setMeshFile(candidate, index, field.text, diskFileSource(), error)) {
            document.apply("Mesh file",
                           [&](Scene& scene, editor::Selection&) { scene = std::move(candidate); });
            field.error.clear();
        } else {
            field.error = error;
        }
    }
    drawRefusal(field.error);
    Scene& scene = document.editScene();
    MeshInstance& mesh = scene.meshes[std::size_t(index)];
    bool& worldCoordinates = state.worldCoordinates;
    ImGui::Checkbox("world coordinates", &worldCoordinates);
    helpTooltip("R / G with X, Y or Z: the world's axes when on, the mesh's own "
                "axes when off.");
    ImGui::Separator();
    const float size =
        std::max({mesh.transform.scale.x, mesh.transform.scale.y, mesh.transform.scale.z});
    if (editTransform(mesh.transform, false, glm::mat4(1.0f), size))
        document.markChanged("Transform");
    ImGui::Separator();
    if (chooseMaterial(scene, mesh.materialOverride, "(glTF materials)"))
        document.markChanged("Material");
    ImGui::Separator();
    drawMeshGltfInspector(session, index, state);
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
