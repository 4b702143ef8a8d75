// The load budget of one glTF file: for vertices, indices, texels and buffer bytes, the
// per-file limit and what is left of the scene's budget, and the refusal that names both.
// Everything is checked against it before it is allocated.
#pragma once

#include "scene/mesh_asset.hpp"

#include <cstdint>
#include <string>

namespace rmsc::gltf {

struct Allowance {
    const char* noun = "";           // "vertices"
    const char* fileLimitName = "";  // the limit's row in docs/limits.md: "glTF vertices"
    const char* sceneLimitName = ""; // "Scene glTF vertices"; "" when only the file's counts
    std::uint64_t fileLimit = 0;     // per glTF file
    std::uint64_t sceneLeft = 0;     // left of the scene's budget (before this file)
    std::uint64_t sceneLimit = 0;    // the scene's whole budget
    std::uint64_t used = 0;          // taken by this file so far

    std::uint64_t allowed() const { return fileLimit < sceneLeft ? fileLimit : sceneLeft; }
    // Takes `amount` more; false (nothing taken) when that would go over allowed().
    bool take(std::uint64_t amount);
    // "33554432 vertices, more than the 16777216 allowed per glTF file (the limit "glTF
    // vertices" in docs/limits.md)", or the same for what is left of the scene's budget.
    std::string refusal(std::uint64_t needed) const;
};

struct FileBudget {
    Allowance vertices, indices, texels, bufferBytes;
};

// The budget of a file loaded with `scene` (the scene's budget as it stands).
FileBudget fileBudget(const GltfBudget& scene);

} // namespace rmsc::gltf
