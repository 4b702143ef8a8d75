// The file browser (Open, Save As, + Mesh and the inspector's file fields): a modal window with
// the folder's listing under the use's filter (editor/file_browser.hpp; "all files" shows the
// rest), folders to go into, Up, and a name field that takes a file name, a path relative to the
// folder or an absolute one. A click on a file puts its name in the field; a double-click, OK or
// Enter chooses it; a folder typed or double-clicked is gone into.
#pragma once

#include "editor/file_browser.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace rmsc::app {

struct FileBrowser {
    bool ask = false;  // open it on the next draw
    std::string title; // "Open scene", ...
    editor::FileKind kind = editor::FileKind::Scene;
    bool saving = false; // Save As: the name may be one that does not exist yet
    std::filesystem::path folder;
    std::string name; // the name field
    bool allFiles = false;
    editor::DirectoryListing listing;
    bool stale = true; // the folder is listed again on the next draw
    std::string error; // why the last choice was refused

    // Opens it at `start`: a file (its folder, with its name in the field), a folder, or "" (the
    // working folder).
    void open(std::string title, editor::FileKind kind, bool saving,
              const std::filesystem::path& start);
};

// Draws the browser while it is open; returns the chosen file once it is chosen (the browser
// then closes).
std::optional<std::filesystem::path> drawFileBrowser(FileBrowser& browser);

} // namespace rmsc::app
