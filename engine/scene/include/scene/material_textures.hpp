// Loading the image files named by scene materials (base colour, normal and roughness textures
// of SDF shapes): read through the FileSource, decoded by stb_image to RGBA8, one image per
// distinct (file, colour space), each at its own resolution. Done while preparing a scene, so
// `rmsc validate` reports bad textures without a GL context.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"
#include "core/limits.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rmsc {

// At most this many distinct textures for SDF materials: the march pass binds each to its own
// texture unit (GLSL 4.5 cannot index a sampler array with a per-pixel material index).
constexpr int kMaxSdfMaterialTextures = limits::kSdfMaterialTextures;
// Decoded texels of all SDF material textures together (each is also limited to
// limits::kTextureDimension a side).
constexpr std::uint64_t kMaxSdfTextureTexels = limits::kSdfTextureTexels;

// A decoded texture and how the GPU must interpret its texels.
struct TextureImage {
    std::filesystem::path path;
    bool srgb = false; // base colour: sRGB-encoded; normal and roughness maps: linear
    Image image;
};

// Reads every texture of `materials`, sets each MaterialTexture::image to its index in
// `textures` (shared by materials naming the same file in the same colour space) and reports
// missing, unreadable, undecodable or oversized files and too many textures at the file name's
// JSON pointer. Each texture's texels are checked, from its header before it is decoded,
// against kMaxSdfTextureTexels and what is left of `sceneBudget` (the scene's texel budget,
// limits::kSceneTexels, shared with its glTF files and sky image; nullptr: none), and taken
// out of it. Returns false if anything was reported.
bool loadMaterialTextures(std::vector<Material>& materials, const std::string& sceneFile,
                          const FileSource& files, Diagnostics& diagnostics,
                          std::vector<TextureImage>& textures, GltfBudget* sceneBudget = nullptr);

} // namespace rmsc
