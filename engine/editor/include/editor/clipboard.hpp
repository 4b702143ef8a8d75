// Copy and paste of selected objects, also between scenes. What is copied is written as the text
// of a scene file (docs/scene-format.md) holding just the copied objects: the SDF nodes (each
// with its world placement and the material it is drawn with) under a plain union root, the
// mesh instances, the lights and the materials they use, with every file path absolute. So the
// viewer can put it on the system clipboard, where it survives opening another scene, and a
// scene file's text copied from elsewhere pastes too. Pasting reads the text as a scene file
// would be read, so bad text is refused with the reader's messages. GL-free.
#pragma once

#include "editor/selection.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc::editor {

// The scene-file text of `items` of `scene` ("" when none of them exists).
std::string clipboardText(const Scene& scene, const std::vector<Selection>& items);

// Reads clipboard text as a scene file. On failure returns nullopt with `error` saying why
// (the reader's first errors, by JSON pointer), and nothing changes.
std::optional<Scene> parseClipboardText(std::string_view text, std::string& error);

struct PasteResult {
    std::vector<Selection> pasted; // in clipboard order: SDF nodes, meshes, lights
    int lightsLeftOut = 0;         // lights past limits::kLights, not pasted
};

// Adds what `clip` holds to `scene`: its SDF nodes next to `near` (as insertSdfNode places a new
// node), keeping their world placement, then its meshes and lights at the end of their lists.
// A union root without a transform of its own pastes as its children, any other root as one
// node. Materials are matched by name: one the scene has already is used as it is, the others
// are added. File paths become relative to the scene's folder when it has a file.
PasteResult pasteClip(Scene& scene, const Selection& near, const Scene& clip);

} // namespace rmsc::editor
