// The editor's choice of SDF map (see editing_map.hpp).
#include "editor/editing_map.hpp"

namespace rmsc::editor {

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
