// What the menus, panels and shortcuts ask of the viewer beyond their own edits of the document
// (those they make themselves): they queue commands while they draw or read the input, and the
// frame loop carries them out in order right after the part that queued them, before the next
// part runs (Viewer::carryOut, viewer_commands.cpp).
#pragma once

#include "scene/scene.hpp"

#include <filesystem>
#include <vector>

namespace rmsc::app {

enum class ViewerCommand {
    Undo,
    Redo,
    Duplicate, // the active object
    Delete,    // everything selected, when anything is
    Copy,      // everything selected, to the system clipboard as scene-file text
    Paste,     // the system clipboard's scene objects, next to the active object
    Group,     // the selected SDF nodes into a new union group (Edit > Group: any operation)
    NewScene,  // asks first when there are unsaved changes
    Open,      // asks for the file (the file browser)
    OpenFile,  // opens `path`, asking first when there are unsaved changes
    DropFile,  // a file dropped on the window: a .json opens (as OpenFile), a .gltf or .glb
               // is added as a mesh where a new shape goes
    ForgetMissingRecent, // drops the recent files that no longer exist
    ClearRecent,         // empties the recent files
    Save,                // asks for a file when the scene has none yet
    SaveAs,              // asks for the file
    AddMesh,             // asks for the glTF file
    ExportScene,         // the export dialog for the whole SDF tree (export_dialog.hpp)
    ExportSelection,     // the export dialog for the selected SDF node
    Screenshot,          // the view, next to the scene file
    Quit,                // asks first when there are unsaved changes
    FrameSelection,      // the camera looks at the selection (or the whole SDF)
    AddSearch,           // the searchable add menu, at the mouse
    ShortcutSheet,       // shows or hides the sheet of every shortcut
    SaveCamera,          // the view becomes the scene's camera
    ResetCamera,         // the view from the scene's camera
    // A light of each type, at the point the view looks at (its focus straight ahead).
    AddDirectionalLight,
    AddPointLight,
    AddSpotLight,
};

// A command and the file it is about (OpenFile, DropFile).
struct QueuedCommand {
    QueuedCommand(ViewerCommand c, std::filesystem::path p = {}) : command(c), path(std::move(p)) {}
    ViewerCommand command;
    std::filesystem::path path;
};

using ViewerCommands = std::vector<QueuedCommand>;

// The command that adds a light of `type`.
ViewerCommand addLightCommand(LightType type);

} // namespace rmsc::app
