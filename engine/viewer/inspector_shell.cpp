// The inspector's shell fields of an SDF node, mesh-shell mode (docs/scene-format.md, "Shells"):
// on or off, the proxy, a bound the content is clipped to, and the proxy's glTF file (applied
// with Enter, resolved against the scene's folder).
#include "inspector.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace rmsc::app {

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
    // The reader's range of "bound": lengths in (0, 10000].
    if (shell.bound)
        changed |=
            numberField("bound", &shell.bound->x, 3, 0.01f, openClosedRange(0.0, 1e4, Unit::Metres),
                        "Half extents of the box the content is clipped to, in the node's "
                        "frame.",
                        {.drag = editor::FloatFieldRange{1e-3f, 1e4f}});
    if (shell.proxy == ShellProxy::Mesh &&
        ImGui::InputText("mesh file", &shell.meshFile, ImGuiInputTextFlags_EnterReturnsTrue)) {
        shell.meshPath = (sceneFolder / shell.meshFile).lexically_normal();
        changed = true;
    }
    return changed;
}

} // namespace rmsc::app
