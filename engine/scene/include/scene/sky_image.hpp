// The equirectangular HDR image of an image sky ("environment": {"sky": {"type": "image"}}),
// decoded with stb_image's float loader (Radiance .hdr; 8-bit formats are linearized by
// stb_image) and read through a FileSource like every other scene input.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"

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

// Loads `path`; problems are reported at `sceneFile` and `pointer` (the sky's "file").
std::optional<SkyImage> loadSkyImage(const std::filesystem::path& path, const FileSource& files,
                                     const std::string& sceneFile, const std::string& pointer,
                                     Diagnostics& diagnostics);

} // namespace rmsc
