// Camera bookmarks (see view_bookmarks.hpp).
#include "editor/view_bookmarks.hpp"

namespace rmsc::editor {

bool ViewBookmarks::store(int slot, const Camera& view) {
    if (slot < 1 || slot > kViewBookmarks) return false;
    views[std::size_t(slot - 1)] = view;
    return true;
}

std::optional<Camera> ViewBookmarks::recall(int slot) const {
    if (slot < 1 || slot > kViewBookmarks) return std::nullopt;
    return views[std::size_t(slot - 1)];
}

} // namespace rmsc::editor
