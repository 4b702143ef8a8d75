// Loading scene material textures (see material_textures.hpp).
#include "scene/material_textures.hpp"

#include "gltf_files.hpp"

#include <map>
#include <utility>

namespace rmsc {

bool loadMaterialTextures(std::vector<Material>& materials, const std::string& sceneFile,
                          const FileSource& files, Diagnostics& diagnostics,
                          std::vector<TextureImage>& textures, GltfBudget* sceneBudget) {
    const int errorsBefore = diagnostics.errorCount();
    std::map<std::pair<std::filesystem::path, bool>, int> known; // -2: failed to load
    std::uint64_t texels = 0;
    for (const TextureImage& t : textures)
        texels += std::uint64_t(t.image.width) * std::uint64_t(t.image.height);
    for (Material& material : materials) {
        const std::pair<MaterialTexture*, bool> slots[] = {{&material.baseColorTexture, true},
                                                           {&material.normalTexture, false},
                                                           {&material.roughnessTexture, false}};
        for (const auto& [texture, srgb] : slots) {
            if (!texture->present()) continue;
            const auto key = std::make_pair(texture->path, srgb);
            if (const auto found = known.find(key); found != known.end()) {
                texture->image = found->second >= 0 ? found->second : -1;
                continue;
            }
            known[key] = -2;
            std::string why;
            const auto bytes = files.read(texture->path, why);
            if (!bytes) {
                diagnostics.error(sceneFile, texture->pointer,
                                  "cannot read texture \"" + texture->file + "\": " + why);
                continue;
            }
            const auto* data = reinterpret_cast<const unsigned char*>(bytes->data());
            // The limits below are checked on the size the header states, before decoding.
            const auto stated = gltf::readImageSize(data, bytes->size(), why);
            if (!stated) {
                diagnostics.error(sceneFile, texture->pointer,
                                  "texture \"" + texture->file +
                                      "\" is not a usable image: " + why);
                continue;
            }
            TextureImage loaded;
            loaded.path = texture->path;
            loaded.srgb = srgb;
            loaded.image.width = stated->width;
            loaded.image.height = stated->height;
            if (int(textures.size()) >= kMaxSdfMaterialTextures) {
                diagnostics.error(sceneFile, texture->pointer,
                                  "texture \"" + texture->file +
                                      "\" is one too many: SDF "
                                      "materials may use at most " +
                                      std::to_string(kMaxSdfMaterialTextures) +
                                      " distinct textures (a file used as base colour and as a "
                                      "linear map counts twice)");
                continue;
            }
            const std::uint64_t withThis =
                texels + std::uint64_t(loaded.image.width) * std::uint64_t(loaded.image.height);
            if (withThis > kMaxSdfTextureTexels) {
                diagnostics.error(sceneFile, texture->pointer,
                                  "texture \"" + texture->file + "\" (" +
                                      std::to_string(loaded.image.width) + "x" +
                                      std::to_string(loaded.image.height) +
                                      ") brings the SDF material textures over the limit of " +
                                      std::to_string(kMaxSdfTextureTexels >> 20) +
                                      " Mi texels in all (the limit \"SDF material texels\")");
                continue;
            }
            const std::uint64_t own =
                std::uint64_t(loaded.image.width) * std::uint64_t(loaded.image.height);
            if (sceneBudget && own > sceneBudget->texels) {
                diagnostics.error(sceneFile, texture->pointer,
                                  "texture \"" + texture->file + "\" (" +
                                      std::to_string(loaded.image.width) + "x" +
                                      std::to_string(loaded.image.height) +
                                      ") brings the scene's images over the limit \"Scene "
                                      "texels\" of " +
                                      std::to_string(limits::kSceneTexels >> 20) +
                                      " Mi texels (glTF images, textures and the sky together)");
                continue;
            }
            if (!gltf::decodeImage(data, bytes->size(), loaded.image, why)) {
                diagnostics.error(sceneFile, texture->pointer,
                                  "texture \"" + texture->file +
                                      "\" is not a usable image: " + why);
                continue;
            }
            texels = withThis;
            if (sceneBudget) sceneBudget->texels -= own;
            known[key] = int(textures.size());
            texture->image = int(textures.size());
            textures.push_back(std::move(loaded));
        }
    }
    return diagnostics.errorCount() == errorsBefore;
}

} // namespace rmsc
