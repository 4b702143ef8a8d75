// Editing material textures with a load check first (see material_texture_edits.hpp).
#include "editor/material_texture_edits.hpp"

#include "scene/material_textures.hpp"
#include "scene/scene_paths.hpp"

namespace rmsc::editor {
namespace {

constexpr TextureSlotInfo kSlots[] = {
    {TextureSlot::BaseColor, "base colour", "base_color_texture", &Material::baseColorTexture,
     false},
    {TextureSlot::Normal, "normal", "normal_texture", &Material::normalTexture, true},
    {TextureSlot::Roughness, "roughness", "roughness_texture", &Material::roughnessTexture, false},
};

// The first error reported at `pointer`, or "".
std::string errorAt(const Diagnostics& diagnostics, const std::string& pointer) {
    for (const Diagnostic& d : diagnostics.items)
        if (d.severity == Severity::Error && d.location == pointer) return d.message;
    return "";
}

} // namespace

std::span<const TextureSlotInfo> textureSlots() {
    return kSlots;
}

const TextureSlotInfo& textureSlotInfo(TextureSlot slot) {
    for (const TextureSlotInfo& info : kSlots)
        if (info.slot == slot) return info;
    return kSlots[0];
}

bool setMaterialTextureFile(Scene& scene, int materialIndex, TextureSlot slot,
                            const std::string& file, const FileSource& files, std::string& error) {
    if (materialIndex < 0 || materialIndex >= int(scene.materials.size())) {
        error = "no such material";
        return false;
    }
    const TextureSlotInfo& info = textureSlotInfo(slot);
    Material& material = scene.materials[std::size_t(materialIndex)];
    MaterialTexture texture = material.*info.member;
    if (file.empty()) { // removing a texture cannot fail
        texture.file.clear();
        texture.path.clear();
        texture.image = -1;
        material.*info.member = texture;
        return true;
    }
    texture.path = resolveScenePath(scene, file);
    texture.file = scene.file.empty() ? texture.path.generic_string() : file;
    texture.pointer = "/materials/" + material.name + "/" + info.key + "/file";
    texture.image = -1;

    // The new image alone first: can it be read and decoded at all?
    Material alone;
    alone.*info.member = texture;
    std::vector<Material> single{alone};
    std::vector<TextureImage> images;
    Diagnostics diagnostics;
    const std::string sceneFile = scene.file.string();
    if (!loadMaterialTextures(single, sceneFile, files, diagnostics, images)) {
        error = errorAt(diagnostics, texture.pointer);
        if (error.empty()) error = diagnostics.format();
        return false;
    }
    // Then with every other texture of the scene: does it stay within the limits? (Compared
    // with the scene as it is, so a problem the scene already has is not blamed on this file.)
    std::vector<Material> current = scene.materials;
    Diagnostics before;
    images.clear();
    loadMaterialTextures(current, sceneFile, files, before, images);
    std::vector<Material> candidate = scene.materials;
    candidate[std::size_t(materialIndex)].*info.member = texture;
    Diagnostics after;
    images.clear();
    loadMaterialTextures(candidate, sceneFile, files, after, images);
    if (after.errorCount() > before.errorCount()) {
        error = errorAt(after, texture.pointer);
        if (error.empty()) error = after.items.back().message; // the limit, at a later texture
        return false;
    }
    material.*info.member = texture; // its image index is set by the scene preparation
    return true;
}

} // namespace rmsc::editor
