// The Inspector panel (right). The Object tab shows what is selected: an SDF node (its shape or
// group operation, material, modifiers, shell and textures), a mesh instance or a light; the
// Render tab the render settings, the camera and the view. Each kind has a file and a function
// of its own (inspector_*.cpp) that takes what it edits. Widgets edit the document's scene in
// place and mark it changed; the frame loop commits one undo step once no widget is active.
#pragma once

#include "editor/animation_playback.hpp"
#include "editor/document.hpp"
#include "editor_session.hpp"
#include "file_field.hpp"
#include "panel_layout.hpp"
#include "prepare/prepared_scene.hpp"
#include "view_settings.hpp"
#include "viewer_commands.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace rmsc::app {

// The file fields of the texture slots of the selected material
// (editor/material_texture_edits.hpp), one per slot, owned by the material's index; a slot's file
// changes only when "apply" loads what was typed.
using TextureFileFields = std::array<FileField, 3>;

// The environment's fields that outlive a frame: the sky image's file being typed, and why the
// last sky type was refused (an image sky chosen before its file, which then shows).
struct EnvironmentFields {
    FileField skyFile;
    std::string skyRefusal;
    bool choosingImage = false;
};

struct InspectorState {
    // Positions shown in world coordinates, and gesture axes the world's (otherwise the
    // object's own).
    bool worldCoordinates = false;
    TextureFileFields textureFiles;
    std::string modifierRefusal; // why the last modifier edit was undone ("" = it was not)
    FileField meshFile;          // the selected mesh's glTF file
    EnvironmentFields environment;
    std::string cameraRefusal; // why the last camera position / target / up was not taken
    // The glTF animation playing (the frame loop advances its mesh's time), what the mesh
    // inspector lists of a glTF file (the newest scene that compiled, set every frame; nullptr
    // before one has), and why the last look through a glTF camera was refused.
    editor::AnimationPlayback playback;
    const PreparedScene* prepared = nullptr;
    std::string gltfCameraRefusal;
};

void drawInspectorPanel(EditorSession& session, InspectorState& state, ViewSettings& view,
                        const PanelLayout& layout, ViewerCommands& commands);
// The file field whose "..." was pressed this frame (its request cleared), or nullptr.
FileField* takeBrowseRequest(InspectorState& state);

// The Object tab, by the kind of the selection.
void drawSdfNodeInspector(editor::Document& document, const std::vector<int>& path,
                          InspectorState& state, ViewerCommands& commands);
void drawMeshInspector(EditorSession& session, int mesh, InspectorState& state,
                       ViewerCommands& commands);
void drawLightInspector(editor::Document& document, int light, ViewerCommands& commands);
// The part of a mesh's inspector about its glTF file: the animation shown, its timeline with
// play / pause, the file's cameras to look through and its scenes to draw.
void drawMeshGltfInspector(EditorSession& session, int mesh, InspectorState& state);

// Parts of an SDF node's inspector; each returns true when it changed the node.
// Lengths drag in steps that follow `size`; `refusal` says why the last edit was undone.
bool editModifiers(SdfNode& node, float size, std::string& refusal);
bool editShell(SdfNode& node, const std::filesystem::path& sceneFolder);
// A profile solid's profile and its own key (depth, offset); drags follow `size`.
bool editProfile(SdfProfile& profile, float size);

// Materials: the choice (-1 is "inherit" for SDF nodes, "the glTF's own" for meshes) with the
// chosen material's fields; returns true on change. And the chosen material's texture files.
bool chooseMaterial(Scene& scene, int& material, const char* noneLabel);
void drawMaterialTextures(editor::Document& document, int material, TextureFileFields& fields);

// The Render tab.
void drawRenderSettingsInspector(editor::Document& document);
void drawEnvironmentInspector(editor::Document& document, EnvironmentFields& fields);
// The scene camera; `refusal` says why the last position / target / up was not taken.
void drawCameraInspector(EditorSession& session, std::string& refusal);
void drawViewInspector(ViewSettings& view);

} // namespace rmsc::app
