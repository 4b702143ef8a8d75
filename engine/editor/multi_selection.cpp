// Plain and Shift-clicks on objects (see multi_selection.hpp).
#include "editor/multi_selection.hpp"

#include <algorithm>

namespace rmsc::editor {

void clickSelect(Document& document, const Selection& item, bool extend) {
    std::vector<Selection>& others = document.alsoSelected;
    if (!extend) {
        document.selection = item;
        others.clear();
        return;
    }
    if (item.empty()) return; // Shift-click on empty space keeps the selection
    if (item == document.selection) {
        // Deselect the active object; the one added before it takes its place.
        document.selection = Selection::none();
        if (!others.empty()) {
            document.selection = others.back();
            others.pop_back();
        }
        return;
    }
    others.erase(std::remove(others.begin(), others.end(), item), others.end());
    if (!document.selection.empty()) others.push_back(document.selection);
    document.selection = item;
}

bool isSelected(const Document& document, const Selection& item) {
    if (item.empty()) return false;
    return item == document.selection ||
           std::find(document.alsoSelected.begin(), document.alsoSelected.end(), item) !=
               document.alsoSelected.end();
}

std::vector<Selection> selectedItems(const Document& document) {
    std::vector<Selection> items = document.alsoSelected;
    if (!document.selection.empty()) items.push_back(document.selection);
    return items;
}

} // namespace rmsc::editor
