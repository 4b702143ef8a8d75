// The sheet of every shortcut (F1, or Help > Keyboard shortcuts): a window over the view listing
// the shortcut table (editor/shortcut_table.hpp) section by section, as docs/viewer.md does.
#pragma once

#include "panel_layout.hpp"

namespace rmsc::app {

// Draws the sheet while `open`; its close button (or Esc) clears `open`.
void drawShortcutSheet(bool& open, const Rect& viewport);

} // namespace rmsc::app
