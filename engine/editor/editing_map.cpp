// The editor's choice of SDF map (see editing_map.hpp).
#include "editor/editing_map.hpp"

#include "editor/scene_edits.hpp"

namespace rmsc::editor {

SdfLiveRange selectionLiveRange(const Scene& scene, const Selection& selection) {
    if (selection.kind != SelectionKind::Sdf) return {};
    const IdRange ids = objectIdRange(scene, selection); // [first, last)
    return ids.last > ids.first ? SdfLiveRange{ids.first, ids.last - 1} : SdfLiveRange{};
}

EditingMaps chooseEditingMaps(const SdfProgram& program, const SdfLiveRange& live,
                              const std::function<bool(const std::string&)>& isReady) {
    EditingMaps maps;
    maps.draw = generateSdfMap(program, SdfStrategy::Buffer);
    if (effectiveSdfStrategy(program, SdfStrategy::Baked) != SdfStrategy::Baked) return maps;
    std::string baked = generateSdfMap(program, SdfStrategy::Baked, {}, live);
    if (isReady(baked)) {
        maps.draw = std::move(baked);
        maps.baked = true;
    } else {
        maps.build = std::move(baked);
    }
    return maps;
}

} // namespace rmsc::editor
