// What each viewer command does: Viewer::carryOut (see viewer_commands.hpp, frame_loop.hpp).
#include "viewer_commands.hpp"

#include "camera_controls.hpp"
#include "document_edits.hpp"
#include "editor/clipboard.hpp"
#include "editor/multi_selection.hpp"
#include "frame_loop.hpp"

namespace rmsc::app {

ViewerCommand addLightCommand(LightType type) {
    switch (type) {
    case LightType::Point:
        return ViewerCommand::AddPointLight;
    case LightType::Spot:
        return ViewerCommand::AddSpotLight;
    case LightType::Directional:
        break;
    }
    return ViewerCommand::AddDirectionalLight;
}

void Viewer::carryOut(ViewerCommands& commands) {
    editor::Document& document = session_.document;
    for (const QueuedCommand& queued : commands) {
        const ViewerCommand command = queued.command;
        switch (command) {
        case ViewerCommand::Undo:
            gizmo_.drag.reset();                        // a drag running is committed, then undone
            editor::pausePlayback(inspector_.playback); // and so is the animation playing
            document.undo();
            break;
        case ViewerCommand::Redo:
            gizmo_.drag.reset();
            editor::pausePlayback(inspector_.playback);
            document.redo();
            break;
        case ViewerCommand::Duplicate:
            duplicateSelection(document);
            break;
        case ViewerCommand::Delete:
            deleteSelection(document);
            break;
        case ViewerCommand::Copy: {
            const std::vector<editor::Selection> items = editor::selectedItems(document);
            const std::string text = editor::clipboardText(document.scene(), items);
            if (text.empty()) break;
            glfwSetClipboardString(window_->handle(), text.c_str());
            messages_.notice("copied " + std::to_string(items.size()) + " object" +
                             (items.size() == 1 ? "" : "s"));
            break;
        }
        case ViewerCommand::Paste: {
            const char* text = glfwGetClipboardString(window_->handle());
            std::string message;
            if (pasteText(document, text ? text : "", message))
                messages_.notice(message);
            else
                messages_.fileError = message;
            break;
        }
        case ViewerCommand::Group:
            groupSelection(document, SdfOp::Union);
            break;
        case ViewerCommand::NewScene:
            requestNew(dialogs_, session_, files_, messages_);
            break;
        case ViewerCommand::Open:
            dialogs_.askForPath(PathPurpose::Open, document.file().empty()
                                                       ? std::filesystem::current_path()
                                                       : document.file());
            break;
        case ViewerCommand::OpenFile:
            requestOpen(dialogs_, queued.path, session_, files_, messages_);
            break;
        case ViewerCommand::DropFile:
            dropFile(queued.path);
            break;
        case ViewerCommand::ForgetMissingRecent:
        case ViewerCommand::ClearRecent:
            forgetRecentFiles(files_, command == ViewerCommand::ForgetMissingRecent, messages_);
            break;
        case ViewerCommand::Save:
            requestSave(dialogs_, session_, files_, messages_, false);
            break;
        case ViewerCommand::SaveAs:
            requestSave(dialogs_, session_, files_, messages_, true);
            break;
        case ViewerCommand::AddMesh:
            dialogs_.newMeshAt = newShapeSpot(newShapePlace()).point;
            dialogs_.askForPath(PathPurpose::AddMesh, document.file().empty()
                                                          ? std::filesystem::current_path()
                                                          : document.file().parent_path());
            break;
        case ViewerCommand::ExportScene:
        case ViewerCommand::ExportSelection: {
            const editor::FlyCamera& camera = session_.camera;
            openExportDialog(export_, document, command == ViewerCommand::ExportSelection,
                             camera.position + camera.forward() * camera.focusDistance);
            break;
        }
        case ViewerCommand::AddDirectionalLight:
        case ViewerCommand::AddPointLight:
        case ViewerCommand::AddSpotLight: {
            const LightType type = command == ViewerCommand::AddPointLight ? LightType::Point
                                   : command == ViewerCommand::AddSpotLight
                                       ? LightType::Spot
                                       : LightType::Directional;
            addLight(document, type, viewFocus());
            break;
        }
        case ViewerCommand::Screenshot:
            screenshotToDefaultFile();
            break;
        case ViewerCommand::Quit:
            dialogs_.afterDiscard = AfterDiscard::Quit;
            requestClose(dialogs_, session_, files_, messages_);
            break;
        case ViewerCommand::FrameSelection:
            frameSelection(session_);
            break;
        case ViewerCommand::AddSearch:
            addSearch_.openAt(input_.mouse);
            break;
        case ViewerCommand::ShortcutSheet:
            shortcutSheet_ = !shortcutSheet_;
            break;
        case ViewerCommand::SaveCamera:
            session_.saveCameraToScene();
            break;
        case ViewerCommand::ResetCamera:
            session_.resetCamera();
            break;
        }
    }
    commands.clear();
}

} // namespace rmsc::app
