// The load budget of one glTF file (see gltf_budget.hpp).
#include "scene/gltf_budget.hpp"

#include <limits>

namespace rmsc::gltf {

bool Allowance::take(std::uint64_t amount) {
    if (amount > allowed() || used > allowed() - amount) return false;
    used += amount;
    return true;
}

std::string Allowance::refusal(std::uint64_t needed) const {
    const std::string head = std::to_string(needed) + " " + noun + ", more than the ";
    if (fileLimit <= sceneLeft)
        return head + std::to_string(fileLimit) + " allowed per glTF file (the limit \"" +
               fileLimitName + "\" in docs/limits.md)";
    return head + std::to_string(sceneLeft) + " left of the scene's " + std::to_string(sceneLimit) +
           " for all its glTF files together (the limit \"" + sceneLimitName +
           "\" in docs/limits.md)";
}

FileBudget fileBudget(const GltfBudget& scene) {
    constexpr std::uint64_t kNoLimit = std::numeric_limits<std::uint64_t>::max();
    FileBudget budget;
    budget.vertices = {"vertices",
                       "glTF vertices",
                       "Scene glTF vertices",
                       limits::kGltfVertices,
                       scene.vertices,
                       limits::kSceneGltfVertices,
                       0};
    budget.indices = {"indices",
                      "glTF indices",
                      "Scene glTF indices",
                      limits::kGltfIndices,
                      scene.indices,
                      limits::kSceneGltfIndices,
                      0};
    budget.texels = {"texels",
                     "glTF texels",
                     "Scene texels",
                     limits::kGltfTexels,
                     scene.texels,
                     limits::kSceneTexels,
                     0};
    // Buffers are freed once the file is loaded: they count per file only.
    budget.bufferBytes = {
        "bytes", "glTF buffer bytes", "", limits::kGltfBufferBytes, kNoLimit, kNoLimit, 0};
    return budget;
}

} // namespace rmsc::gltf
