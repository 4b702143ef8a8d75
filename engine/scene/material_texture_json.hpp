// Reading and writing the texture fields of a scene material ("base_color_texture",
// "normal_texture", "roughness_texture"; docs/scene-format.md, "Material textures"). Only the
// JSON is checked here; the image files are read and decoded by material_textures.hpp.
#pragma once

#include "json_reader.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rmsc {

// The material keys this file reads, for the unknown-key check of the material object.
const std::vector<std::string>& materialTextureKeys();

// The texture members of a Material, in the order of materialTextureKeys().
const std::vector<MaterialTexture Material::*>& materialTextureMembers();

// Reads every texture field of the material object at `pointer`; relative files are resolved
// against `sceneFolder`. Problems are reported with their JSON pointers.
void readMaterialTextures(const JsonReader& reader, const Json& object, const std::string& pointer,
                          const std::filesystem::path& sceneFolder, Material& material);

// Adds the material's textures to its JSON object (the inverse of readMaterialTextures).
void writeMaterialTextures(const Material& material, Json& object);

} // namespace rmsc
