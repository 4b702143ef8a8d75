// Which SDF map the editor draws with (sdf/glsl_codegen.hpp): the one that bakes everything but
// the selected subtree once its programs are ready, the buffer map until then. A drag of the
// selection then changes buffer contents only, and the rest of the scene runs baked.
#pragma once

#include "editor/selection.hpp"
#include "scene/scene.hpp"
#include "sdf/glsl_codegen.hpp"
#include "sdf/program.hpp"

#include <functional>
#include <string>

namespace rmsc::editor {

struct EditingMaps {
    std::string draw;   // the map to draw with now
    std::string build;  // the map to build in the background ("" when `draw` is it)
    bool baked = false; // `draw` is the baked map (with the selection live)
};

// The object ids of the selected SDF node and its subtree; empty when the selection is no SDF
// node (a mesh, a light, nothing).
SdfLiveRange selectionLiveRange(const Scene& scene, const Selection& selection);

// `live`: the selection's object ids (empty when nothing in the SDF is selected). `isReady`:
// are a map's programs built (or warm in the driver's cache)? Scenes too large for generated
// code get the interpreter, which never needs another build.
EditingMaps chooseEditingMaps(const SdfProgram& program, const SdfLiveRange& live,
                              const std::function<bool(const std::string&)>& isReady);

} // namespace rmsc::editor
