// Editing the image textures of scene materials (base colour, normal and roughness maps of SDF
// shapes) from the editor: the three slots by name, and setting a slot's file only after the
// image has loaded, so a missing or broken file leaves the scene as it was and says why.
// GL-free: images are read through a FileSource and decoded as the scene preparation does.
#pragma once

#include "core/file_source.hpp"
#include "scene/scene.hpp"

#include <span>
#include <string>

namespace rmsc::editor {

enum class TextureSlot { BaseColor, Normal, Roughness };

// One texture slot of a Material as the inspector shows it.
struct TextureSlotInfo {
    TextureSlot slot;
    const char* label; // for the inspector
    const char* key;   // the material key in the scene file
    MaterialTexture Material::*member;
    bool hasStrength; // normal maps: "strength" scales the map's x and y
};

// The three slots, in the order of the scene format.
std::span<const TextureSlotInfo> textureSlots();
const TextureSlotInfo& textureSlotInfo(TextureSlot slot);

// Sets the file of texture `slot` of scene.materials[materialIndex] to `file` (relative files
// are resolved against the scene file's folder, or for a scene without a file the current
// folder, and then stored absolute). The image is read and decoded first, and every material
// texture of the scene is loaded with it in place (the limits on the number of textures and
// texels); when anything about the new file fails, returns false with `error` saying why and
// `scene` is unchanged. An empty `file` removes the texture. Scale, sharpness and strength are
// kept.
bool setMaterialTextureFile(Scene& scene, int materialIndex, TextureSlot slot,
                            const std::string& file, const FileSource& files, std::string& error);

} // namespace rmsc::editor
