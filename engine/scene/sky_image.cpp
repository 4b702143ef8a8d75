// Decoding sky images with stb_image's stbi_loadf_from_memory.
#include "scene/sky_image.hpp"

#include "core/limits.hpp"
#include "gltf_files.hpp"

#include <stb_image.h>

#include <limits>

namespace rmsc {

std::optional<SkyImage> loadSkyImage(const std::filesystem::path& path, const FileSource& files,
                                     const std::string& sceneFile, const std::string& pointer,
                                     Diagnostics& diagnostics, GltfBudget* sceneBudget) {
    std::string why;
    std::optional<std::string> bytes;
    try {
        bytes = files.read(path, why);
    } catch (const std::exception& e) {
        why = e.what();
    }
    if (!bytes) {
        diagnostics.error(sceneFile, pointer,
                          "cannot read the sky image \"" + path.string() + "\": " + why);
        return std::nullopt;
    }
    if (bytes->empty() || bytes->size() > std::size_t(std::numeric_limits<int>::max())) {
        diagnostics.error(sceneFile, pointer,
                          "the sky image \"" + path.string() + "\" is empty or too large");
        return std::nullopt;
    }
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes->data());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, int(bytes->size()), &width, &height, &channels)) {
        // stb_image refuses PNG and JPEG headers over its own size limit as if they were not
        // images: the glTF reader's header parse names them too large.
        std::string sizeWhy;
        if (!gltf::readImageSize(data, bytes->size(), sizeWhy) &&
            sizeWhy.find("expected at most") != std::string::npos) {
            diagnostics.error(sceneFile, pointer, "the sky " + sizeWhy);
            return std::nullopt;
        }
        const char* reason = stbi_failure_reason();
        diagnostics.error(sceneFile, pointer,
                          "\"" + path.string() + "\" is not a decodable image (" +
                              (reason ? reason : "unknown format") +
                              "); expected an equirectangular Radiance .hdr image");
        return std::nullopt;
    }
    if (width <= 0 || height <= 0 || width > limits::kTextureDimension ||
        height > limits::kTextureDimension) {
        diagnostics.error(sceneFile, pointer,
                          "the sky image is " + std::to_string(width) + "x" +
                              std::to_string(height) + ", expected at most " +
                              std::to_string(limits::kTextureDimension) + " on each side");
        return std::nullopt;
    }
    const std::uint64_t texels = std::uint64_t(width) * std::uint64_t(height);
    if (sceneBudget && texels > sceneBudget->texels) {
        diagnostics.error(sceneFile, pointer,
                          "the sky image (" + std::to_string(width) + "x" + std::to_string(height) +
                              ") brings the scene's images over the limit \"Scene texels\" of " +
                              std::to_string(limits::kSceneTexels >> 20) +
                              " Mi texels (glTF images, textures and the sky together)");
        return std::nullopt;
    }
    stbi_set_flip_vertically_on_load_thread(0);
    float* pixels = stbi_loadf_from_memory(data, int(bytes->size()), &width, &height, &channels, 3);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        diagnostics.error(sceneFile, pointer,
                          std::string("the sky image could not be decoded (") +
                              (reason ? reason : "unknown") + ")");
        return std::nullopt;
    }
    SkyImage image;
    image.width = width;
    image.height = height;
    if (sceneBudget) sceneBudget->texels -= texels;
    image.rgb.assign(pixels, pixels + std::size_t(width) * std::size_t(height) * 3);
    stbi_image_free(pixels);
    return image;
}

} // namespace rmsc
