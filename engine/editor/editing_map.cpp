// The editor's choice of SDF map (see editing_map.hpp).
#include "editor/editing_map.hpp"

#include "editor/scene_edits.hpp"

namespace rmsc::editor {

SdfLiveRange selectionLiveRange(const Scene& scene, const Selection& selection) {
    if (selection.kind != SelectionKind::Sdf) return {};
    const IdRange ids = objectIdRange(scene, selection); // [first, last)
    return ids.last > ids.first ? SdfLiveRange{ids.first, ids.last - 1} : SdfLiveRange{};
}

EditingMaps chooseEditingMaps(const SdfProgram& program, const SdfProgram& interpreted,
                              const SdfLiveRange& live,
                              const std::function<bool(const std::string&)>& isReady,
                              SdfCellFit cellFit) {
    struct Candidate {
        std::string map;
        EditingMapKind kind;
        bool ready = false;
    };
    std::vector<Candidate> byPreference; // the order to draw in
    if (effectiveSdfStrategy(program, SdfStrategy::Baked) == SdfStrategy::Baked) {
        byPreference.push_back(
            {generateSdfMap(program, SdfStrategy::Baked, {}, live), EditingMapKind::Baked});
        byPreference.push_back(
            {generateSdfMap(program, SdfStrategy::Buffer), EditingMapKind::Buffer});
    } else {
        std::string anyGrid = generateSdfMap(program, SdfStrategy::Cells);
        std::string fitted = generateSdfMap(program, SdfStrategy::Cells, {}, {}, cellFit);
        if (fitted != anyGrid) // (one text where the grid fits nothing more, or for the lean loop)
            byPreference.push_back({std::move(fitted), EditingMapKind::Cells});
        byPreference.push_back({std::move(anyGrid), EditingMapKind::Cells});
    }
    byPreference.push_back(
        {generateSdfMap(interpreted, SdfStrategy::Interpreter), EditingMapKind::Interpreter});

    EditingMaps maps;
    for (Candidate& candidate : byPreference) {
        candidate.ready = isReady(candidate.map);
        if (!candidate.ready) maps.build.push_back(candidate.map); // preference order too
    }
    for (Candidate& candidate : byPreference)
        if (candidate.ready) {
            maps.draw = std::move(candidate.map);
            maps.kind = candidate.kind;
            break;
        }
    return maps;
}

std::string_view editingMapName(EditingMapKind kind) {
    switch (kind) {
    case EditingMapKind::Baked:
        return "baked";
    case EditingMapKind::Buffer:
        return "buffer";
    case EditingMapKind::Interpreter:
        return "interpreter";
    case EditingMapKind::Cells:
        return "cells";
    }
    return "";
}

} // namespace rmsc::editor
