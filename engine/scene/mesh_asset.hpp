// A glTF file loaded into plain CPU arrays: triangle primitives already transformed by the
// file's node hierarchy, with their materials and decoded textures. Uploaded by
// render/gpu_mesh.hpp; instanced by Scene::meshes.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

struct MeshVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

// An 8-bit RGBA image, rows top to bottom.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

struct MeshMaterial {
    std::string name;
    glm::vec4 baseColorFactor{1.0f}; // linear RGBA
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    int baseColorTexture = -1; // index into MeshAsset::images, sRGB
    bool doubleSided = false;
};

// Triangles in the asset's root space (node transforms applied), always indexed.
struct MeshPrimitive {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;
    int material = -1; // index into MeshAsset::materials, -1 for the glTF default material
};

struct MeshAsset {
    std::filesystem::path path;
    std::vector<MeshPrimitive> primitives;
    std::vector<MeshMaterial> materials;
    std::vector<Image> images;
    glm::vec3 boundsMin{0.0f}; // axis-aligned bounds of all primitives
    glm::vec3 boundsMax{0.0f};
};

// Loads a .gltf or .glb through `files`. Every problem is reported to `diagnostics` with the
// file and the glTF element ("/meshes/0/primitives/1/indices"); returns nullopt on error.
std::optional<MeshAsset> loadGltf(const std::filesystem::path& path, const FileSource& files,
                                  Diagnostics& diagnostics);

} // namespace rmsc
