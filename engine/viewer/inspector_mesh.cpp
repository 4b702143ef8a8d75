// The inspector for a mesh instance: name, its glTF file, transform and material override (see
// inspector.hpp).
#include "inspector.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace rmsc::app {

void drawMeshInspector(editor::Document& document, int index, bool& worldCoordinates,
                       ViewerCommands& commands) {
    Scene& scene = document.editScene();
    MeshInstance& mesh = scene.meshes[std::size_t(index)];
    if (ImGui::InputText("name", &mesh.name)) document.markChanged("Rename");
    ImGui::TextDisabled("file: %s", mesh.file.c_str());
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
    drawDuplicateDeleteButtons(commands);
}

} // namespace rmsc::app
