// The equirectangular HDR image of an image sky ("environment": {"sky": {"type": "image"}}),
// decoded with stb_image's float loader (Radiance .hdr; 8-bit formats are linearized by
// stb_image) and read through a FileSource like every other scene input.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"
#include "scene/mesh_asset.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

// Linear RGB floats, rows top (+Y, the zenith) to bottom.
struct SkyImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
};

// Loads `path`; problems are reported at `sceneFile` and `pointer` (the sky's "file"). The
// size its header states is checked before decoding: at most limits::kTextureDimension a side
// (a PNG or JPEG too large for stb_image to read is still named too large) and within what is
// left of `sceneBudget` (the scene's texel budget, limits::kSceneTexels, shared with its glTF
// files and textures; nullptr: none), from which its texels are then taken.
std::optional<SkyImage> loadSkyImage(const std::filesystem::path& path, const FileSource& files,
                                     const std::string& sceneFile, const std::string& pointer,
                                     Diagnostics& diagnostics, GltfBudget* sceneBudget = nullptr);

} // namespace rmsc
