// Which SDF map the editor draws (sdf/glsl_codegen.hpp), from those whose programs are ready:
// best the one that bakes everything but the selected subtree, so a drag of the selection
// changes buffer contents only and the rest of the scene runs baked; then the buffer map; then
// the interpreter, whose text depends only on the kinds of shapes used, so it is usually ready
// after a structural edit (add, delete, duplicate, regroup) and draws the edited scene in the
// edit's own frame. Scenes too large for generated code draw with the cells map (the program
// pruned per cell, sdf/cell_pruning.hpp), whose text too depends only on the kinds of shapes
// (and on what the grid's lists fit: SdfCellFit), then the interpreter. The maps that are not
// ready are built in the background meanwhile.
#pragma once

#include "editor/selection.hpp"
#include "scene/scene.hpp"
#include "sdf/glsl_codegen.hpp"
#include "sdf/program.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rmsc::editor {

enum class EditingMapKind {
    Baked,       // baked, the selection live
    Buffer,      // every number from the buffer
    Interpreter, // the interpreter
    Cells,       // the interpreter on the program pruned per cell (scenes too large for the rest)
};

struct EditingMaps {
    std::string draw; // the best map that is ready, "" when none is: keep the picture on screen
    EditingMapKind kind = EditingMapKind::Interpreter; // what `draw` is
    // The maps not ready, to build in the background in preference order: the baked map, the
    // buffer map (drawn after the next change of selection), the interpreter (after the next
    // structural edit; its first build is the slowest, up to half a minute on llvmpipe).
    std::vector<std::string> build;
};

// The object ids of the selected SDF node and its subtree; empty when the selection is no SDF
// node (a mesh, a light, nothing).
SdfLiveRange selectionLiveRange(const Scene& scene, const Selection& selection);

// `program`: the tree as generated code runs it (the editor compiles it without the bounding
// hierarchy, whose order follows where parts are). `interpreted`: the same tree as the
// interpreter runs it, with the hierarchy (the interpreter's text does not depend on the order,
// and the hierarchy lets it skip parts). `live`: the selection's object ids (empty when nothing
// in the SDF is selected). `isReady`: are a map's programs built (or warm in the driver's
// cache)? Scenes too large for generated code have the cells map of `program` (the tree the
// viewer prunes into cells, so the map reads the lists as the pruning writes them: lean or
// postfix) and the interpreter of `interpreted`. `cellFit`: what the viewer's grid of `program`
// fits (sdfCellFit; nothing while it has none): where that is more than nothing, the map for it
// first, then the one for any grid (drawn meanwhile, and after an edit that makes a list long
// or deep: the first map is then one the new grid fits, or the one for any grid).
EditingMaps chooseEditingMaps(const SdfProgram& program, const SdfProgram& interpreted,
                              const SdfLiveRange& live,
                              const std::function<bool(const std::string&)>& isReady,
                              SdfCellFit cellFit = {});

std::string_view editingMapName(EditingMapKind kind); // "baked", "buffer", "interpreter", "cells"

} // namespace rmsc::editor
