// A file name field whose text is applied (Enter or "apply") rather than set as it is typed, for
// keys whose file must load before the scene takes it (a mesh's glTF, a texture, the sky image):
// the text being typed, the file it was filled from, why the last apply was refused, and a
// "..." button that opens the file browser for it (its choice is put in the field and applied).
#pragma once

#include "editor/file_browser.hpp"

#include <string>
#include <string_view>

namespace rmsc::app {

struct FileField {
    int owner = -1; // what the text belongs to (a mesh's or a material's index; 0 for the sky)
    std::string shownFile; // the owner's file when the text was last filled from it
    std::string text;      // the file name being typed
    std::string error;     // why the last apply was refused ("" = it was not)
    editor::FileKind kind = editor::FileKind::Texture; // what the browser lists for it
    bool browse = false;   // "..." was pressed: the frame loop opens the browser for it
    bool applyNow = false; // the browser chose a file: applied on the next draw
};

// Draws `field` (label `label`, hover help `help`) for `file`, the current file of `owner`; the
// text is filled again when the owner or its file changed by other means (selection, undo,
// reload). Returns true when the text is to be applied: the caller tries it and sets
// `field.error` to why it was refused, or clears it.
bool drawFileField(const char* label, FileField& field, int owner, const std::string& file,
                   std::string_view help, editor::FileKind kind);

// A refusal's reason in the inspector's warning colour (nothing when `error` is empty).
void drawRefusal(const std::string& error);

} // namespace rmsc::app
