// A glTF file loaded into plain CPU arrays: triangle, line and point primitives already
// transformed by the file's node hierarchy, with their materials and decoded textures. Uploaded by
// render/gpu_mesh.hpp; instanced by Scene::meshes.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"
#include "core/limits.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cmath>
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
    glm::vec2 uv;          // TEXCOORD_0, (0, 0) when absent
    glm::vec2 uv1;         // TEXCOORD_1, (0, 0) when absent
    glm::vec4 tangent;     // xyz = unit tangent (direction of +u), w = +-1 bitangent sign
    glm::vec4 color{1.0f}; // COLOR_0 as linear RGBA (alpha 1 for a VEC3), (1, 1, 1, 1) when absent
};

// An 8-bit RGBA image, rows top to bottom.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// How a glTF texture is sampled: the glTF sampler's GL enums (glTF 2.0 section 5.26), with the
// defaults for a texture without a sampler (repeat, linear with linear mipmaps).
struct MeshSampler {
    int magFilter = 0x2601; // GL_LINEAR
    int minFilter = 0x2703; // GL_LINEAR_MIPMAP_LINEAR
    int wrapS = 0x2901;     // GL_REPEAT
    int wrapT = 0x2901;
};

// KHR_texture_transform of one texture slot: uv' = T(offset) * R(rotation) * S(scale) * uv,
// with the extension's rotation matrix (counter-clockwise in UV space, radians).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;
    glm::vec2 scale{1.0f};

    // The extension's translation * rotation * scale, column-major (as GLSL takes it):
    // u' = ox + cos(r) sx u + sin(r) sy v, v' = oy - sin(r) sx u + cos(r) sy v.
    glm::mat3 matrix() const {
        const float c = std::cos(rotation), s = std::sin(rotation);
        return glm::mat3(glm::vec3(c * scale.x, -s * scale.x, 0.0f),
                         glm::vec3(s * scale.y, c * scale.y, 0.0f), glm::vec3(offset, 1.0f));
    }
    glm::vec2 apply(glm::vec2 uv) const { return glm::vec2(matrix() * glm::vec3(uv, 1.0f)); }
};

// One texture slot of a material (a glTF textureInfo): the image, its sampler and the
// TEXCOORD set it reads. image = -1: the slot is empty.
struct MeshTextureRef {
    int image = -1;   // index into MeshAsset::images
    int texCoord = 0; // 0 = TEXCOORD_0, 1 = TEXCOORD_1 (KHR_texture_transform may override it)
    MeshSampler sampler;
    TextureTransform transform; // KHR_texture_transform; the identity without it

    bool present() const { return image >= 0; }
};

// glTF alphaMode (glTF 2.0 section 3.9.4).
enum class AlphaMode { Opaque, Mask, Blend };

// A glTF metallic-roughness material with every texture of the core specification.
struct MeshMaterial {
    std::string name;
    glm::vec4 baseColorFactor{1.0f}; // linear RGBA
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    float emissiveStrength = 1.0f;   // KHR_materials_emissive_strength, multiplies emissiveFactor
    MeshTextureRef baseColorTexture; // sRGB, multiplies baseColorFactor
    MeshTextureRef metallicRoughnessTexture; // linear: B = metallic, G = roughness
    MeshTextureRef normalTexture;            // linear, tangent space
    float normalScale = 1.0f;                // normalTexture.scale: scales the map's x and y
    MeshTextureRef emissiveTexture;          // sRGB, multiplies the emissive factor
    MeshTextureRef occlusionTexture;         // linear: R = ambient occlusion
    float occlusionStrength = 1.0f;          // occlusionTexture.strength: 0 = no effect
    bool doubleSided = false; // false: back faces are culled; true: lit with flipped normals
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f; // MASK: drawn where alpha >= alphaCutoff
    bool unlit = false;       // KHR_materials_unlit: the base colour as it is, no lighting
};

// What a primitive's indices list: glTF's modes 4 to 6 become triangles, 1 to 3 line segments
// (strips and loops unrolled into pairs), 0 points.
enum class PrimitiveMode { Triangles, Lines, Points };

// The indices one element of `mode` takes: 3, 2 or 1.
inline std::size_t indicesPerElement(PrimitiveMode mode) {
    return mode == PrimitiveMode::Triangles ? 3 : mode == PrimitiveMode::Lines ? 2 : 1;
}

// A skinned vertex's four joints and weights of each set (JOINTS_0 / WEIGHTS_0, JOINTS_1 /
// WEIGHTS_1; zero weights for a set the file lacks). Joints index the skin's joints.
struct MeshSkinVertex {
    glm::uvec4 joints0{0u};
    glm::uvec4 joints1{0u};
    glm::vec4 weights0{0.0f};
    glm::vec4 weights1{0.0f};
};

// Triangles, line segments or points in the asset's root space (node transforms, morph weights
// and skins of its pose applied), always indexed. Lines and points without NORMAL have zero
// normals (nothing to compute them from).
struct MeshPrimitive {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices; // indicesPerElement(mode) per element
    PrimitiveMode mode = PrimitiveMode::Triangles;
    int material = -1; // index into MeshAsset::materials, -1 for the glTF default material
    // Skinned primitives only (empty otherwise), for skinning on the GPU: the vertices before
    // any joint moves them (morphed, in the skinned mesh's space: the bind pose), each one's
    // joints and weights, and where its node's matrices start in MeshAsset::jointMatrices.
    // `vertices` are these skinned on the CPU with the same matrices (what picking reads).
    std::vector<MeshVertex> bindVertices;
    std::vector<MeshSkinVertex> skin;
    int jointBase = -1;
    bool morphed = false; // bindVertices change with the pose (the primitive has morph targets)
};

struct MeshRig; // scene/mesh_rig.hpp

struct MeshAsset {
    std::filesystem::path path;
    // What posing needs (mesh_pose.hpp): the file's meshes, nodes, skins, animations, cameras.
    // Shared by copies of the asset; never changed after loading.
    std::shared_ptr<const MeshRig> rig;
    std::vector<MeshPrimitive> primitives;
    std::vector<MeshMaterial> materials;
    std::vector<Image> images;
    std::vector<Light> lights; // KHR_lights_punctual lights, in the asset's root space
    // Per skinned node of the pose, from MeshPrimitive::jointBase: the node's world matrix (for
    // vertices whose weights are all zero), then world(joint) * inverseBindMatrix for each of
    // its skin's joints (at most limits::kGltfJoints). Empty without skins.
    std::vector<glm::mat4> jointMatrices;
    glm::vec3 boundsMin{0.0f}; // axis-aligned bounds of all primitives
    glm::vec3 boundsMax{0.0f};
};

// What the glTF files of one scene may still hold together (limits::kSceneGltf*), and the
// texels its images may still take (limits::kSceneTexels: glTF images, material textures and the
// sky image). Each file or image loaded with it takes what it holds out of it; one that would
// take more is refused.
struct GltfBudget {
    std::uint64_t vertices = limits::kSceneGltfVertices;
    std::uint64_t indices = limits::kSceneGltfIndices;
    std::uint64_t texels = limits::kSceneTexels;
};

// Loads a .gltf or .glb through `files`. Every problem is reported to `diagnostics` with the
// file and the glTF element ("/meshes/0/primitives/1/indices"); returns nullopt on error.
// Checked before anything is allocated: the per-file limits (vertices, indices, texels, buffer
// bytes) and what is left of `sceneBudget`, from which the asset's share is then taken.
// `scene`: the glTF scene to draw, -1 for the file's default one (a scene that does not exist is
// refused, listing those that do). The asset is baked at its rest pose (mesh_pose.hpp poses it).
std::optional<MeshAsset> loadGltf(const std::filesystem::path& path, const FileSource& files,
                                  Diagnostics& diagnostics, GltfBudget& sceneBudget,
                                  int scene = -1);
// The same with a scene budget of its own (a glTF file opened by itself).
std::optional<MeshAsset> loadGltf(const std::filesystem::path& path, const FileSource& files,
                                  Diagnostics& diagnostics);

} // namespace rmsc
