// Camera bookmarks: up to nine views of the viewer (place, direction, roll and projection),
// stored with Ctrl+1..9 and recalled with 1..9 for the session (not written to the scene file).
// GL-free.
#pragma once

#include "scene/scene.hpp"

#include <array>
#include <optional>

namespace rmsc::editor {

constexpr int kViewBookmarks = 9;

struct ViewBookmarks {
    // Slot n (1..kViewBookmarks) is views[n - 1].
    std::array<std::optional<Camera>, kViewBookmarks> views;

    // Keeps `view` in slot `slot` (1..9); false for another slot.
    bool store(int slot, const Camera& view);
    // The view kept in slot `slot`, or nullopt when it is empty or not a slot.
    std::optional<Camera> recall(int slot) const;
};

} // namespace rmsc::editor
