// The inspector for a mesh instance: name, its glTF file (taken only when it loads,
// editor/mesh_file_edits.hpp), transform, material override and the glTF animation shown with
// its time (see inspector.hpp).
#include "inspector.hpp"

#include "editor/mesh_file_edits.hpp"
#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace rmsc::app {

void drawMeshInspector(editor::Document& document, int index, InspectorState& state,
                       ViewerCommands& commands) {
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
    // The glTF animation shown and its time: dragging the time scrubs it (each change poses
    // the mesh again when the scene is prepared).
    if (ImGui::InputText("animation", &mesh.animation)) document.markChanged("Animation");
    helpTooltip("The glTF animation shown, by name or index (\"0\"); empty for the rest pose.");
    float time = float(mesh.time);
    // The reader takes any time >= 0.
    if (numberField("time", &time, 1, 0.01f, {0.0, ParamRange{}.max, false, false, Unit::Seconds},
                    "Seconds into the animation; drag to scrub.", {.format = "%.2f s"})) {
        mesh.time = time;
        document.markChanged("Animation time");
    }
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
