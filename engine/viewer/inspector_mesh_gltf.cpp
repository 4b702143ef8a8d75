// The glTF part of a mesh's inspector: the animation shown (chosen from the file's), its
// timeline with play / pause (the frame loop advances the time while playing), the file's
// cameras to look through and its scenes to draw (see inspector.hpp). What it lists comes from
// the newest scene that compiled (editor/gltf_contents.hpp).
#include "inspector.hpp"

#include "editor/gltf_contents.hpp"
#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace rmsc::app {

namespace {

// The name an animation is saved by: its name when it has one, else its index.
std::string animationKey(const std::string& label, std::size_t index) {
    const std::string number = std::to_string(index);
    return label.size() > number.size() + 1 ? label.substr(number.size() + 1) : number;
}

// The animation choice, the timeline and play / pause, for a file that has animations.
void drawTimeline(editor::Document& document, int index, const editor::GltfContents& contents,
                  editor::AnimationPlayback& playback) {
    MeshInstance& mesh = document.editScene().meshes[std::size_t(index)];
    const int shown = contents.animation;
    const char* preview =
        shown >= 0 ? contents.animations[std::size_t(shown)].c_str() : "(rest pose)";
    if (ImGui::BeginCombo("animation", preview)) {
        if (ImGui::Selectable("(rest pose)", shown < 0)) {
            editor::pausePlayback(playback);
            mesh.animation.clear();
            document.markChanged("Animation");
        }
        for (std::size_t a = 0; a < contents.animations.size(); ++a)
            if (ImGui::Selectable(contents.animations[a].c_str(), int(a) == shown)) {
                mesh.animation = animationKey(contents.animations[a], a);
                document.markChanged("Animation");
            }
        ImGui::EndCombo();
    }
    helpTooltip("The glTF animation shown, from the file's; the rest pose shows none.");
    if (shown < 0 || mesh.animation.empty()) return;
    const double duration = contents.durations[std::size_t(shown)];
    const bool playing = playback.playing && playback.mesh == index;
    if (ImGui::Button(playing ? "Pause" : "Play")) {
        if (playing) {
            editor::pausePlayback(playback);
        } else {
            mesh.time = editor::startPlayback(playback, index, mesh.time, duration);
            document.markChanged("Play animation");
        }
    }
    helpTooltip("Plays the animation in real time, or pauses it where it is.");
    ImGui::SameLine();
    ImGui::Checkbox("loop", &playback.loop);
    helpTooltip("Plays again from the start at the end; otherwise stops there.");
    float time = float(mesh.time);
    char format[64];
    std::snprintf(format, sizeof format, "%%.2f s / %.2f s", duration);
    if (ImGui::SliderFloat("timeline", &time, 0.0f, float(duration), format)) {
        editor::pausePlayback(playback); // scrubbing takes the time over
        mesh.time = std::max(0.0f, time);
        document.markChanged("Animation time");
    }
    helpTooltip("Seconds into the animation, from 0 to its last key; drag to scrub.");
}

} // namespace

void drawMeshGltfInspector(EditorSession& session, int index, InspectorState& state) {
    editor::Document& document = session.document;
    const MeshInstance& mesh = document.scene().meshes[std::size_t(index)];
    // The newest compiled scene, as long as it still shows this mesh's file.
    const PreparedScene* prepared = state.prepared;
    std::optional<editor::GltfContents> contents;
    if (prepared && std::size_t(index) < prepared->scene.meshes.size() &&
        prepared->scene.meshes[std::size_t(index)].path == mesh.path)
        contents = editor::gltfContents(*prepared, index);
    if (!contents) {
        // Not loaded (yet): the animation by name or index, and its time.
        MeshInstance& edited = document.editScene().meshes[std::size_t(index)];
        if (ImGui::InputText("animation", &edited.animation)) document.markChanged("Animation");
        helpTooltip("The glTF animation shown, by name or index (\"0\"); empty for the rest "
                    "pose.");
        float time = float(edited.time);
        if (numberField("time", &time, 1, 0.01f,
                        {0.0, ParamRange{}.max, false, false, Unit::Seconds},
                        "Seconds into the animation; drag to scrub.", {.format = "%.2f s"})) {
            edited.time = time;
            document.markChanged("Animation time");
        }
        return;
    }
    if (contents->animations.empty())
        ImGui::TextDisabled("the file has no animations");
    else
        drawTimeline(document, index, *contents, state.playback);

    if (!contents->cameras.empty()) {
        ImGui::Separator();
        ImGui::TextUnformatted("glTF cameras");
        for (std::size_t c = 0; c < contents->cameras.size(); ++c) {
            ImGui::PushID(int(c));
            if (ImGui::SmallButton("view")) {
                std::string why;
                if (const std::optional<Camera> view =
                        editor::gltfCameraView(*prepared, index, int(c), why)) {
                    session.lookThrough(*view);
                    state.gltfCameraRefusal.clear();
                } else {
                    state.gltfCameraRefusal = why;
                }
            }
            ImGui::SameLine();
            ImGui::TextUnformatted(contents->cameras[c].c_str());
            ImGui::PopID();
        }
        helpTooltip("Looks through the camera, placed by its node at the animation's time and "
                    "by the mesh's transform. The scene's camera takes it when saved to it.");
        drawRefusal(state.gltfCameraRefusal);
    }
    if (contents->scenes.size() > 1) {
        ImGui::Separator();
        const char* preview = contents->scene >= 0
                                  ? contents->scenes[std::size_t(contents->scene)].c_str()
                                  : "(every root node)";
        if (ImGui::BeginCombo("glTF scene", preview)) {
            for (std::size_t s = 0; s < contents->scenes.size(); ++s)
                if (ImGui::Selectable(contents->scenes[s].c_str(), int(s) == contents->scene))
                    document.apply("glTF scene", [&](Scene& scene, editor::Selection&) {
                        scene.meshes[std::size_t(index)].gltfScene = int(s);
                    });
            ImGui::EndCombo();
        }
        helpTooltip("Which of the file's scenes the mesh draws (the file's default when none is "
                    "chosen).");
    }
}

} // namespace rmsc::app
