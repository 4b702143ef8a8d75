// The searchable add menu (Shift+A over the view): a popup at the mouse with a search field and
// every item of editor/add_search.hpp that matches what is typed; Up / Down move the highlight,
// Enter (or a click) adds the highlighted item, Esc closes it. Shapes and groups are added as
// the Add menu adds them (document_edits.hpp: a shape in front of the camera, where `place`
// says); lights and the mesh are queued as commands.
#pragma once

#include "document_edits.hpp"
#include "editor/document.hpp"
#include "viewer_commands.hpp"

#include <glm/glm.hpp>

#include <string>

namespace rmsc::app {

struct AddSearchMenu {
    bool askOpen = false; // open it on the next draw, at `at`
    bool open = false;    // it is open: the view's keys do not fly the camera
    glm::vec2 at{0.0f};   // window pixels
    std::string query;
    int highlighted = 0; // row among the matches

    void openAt(glm::vec2 mouse) {
        askOpen = true;
        at = mouse;
    }
};

void drawAddSearchMenu(AddSearchMenu& menu, editor::Document& document, const NewShapePlace& place,
                       ViewerCommands& commands);

} // namespace rmsc::app
