// Every size limit on what rmsc reads, in one place. The readers refuse input over a limit with
// an error naming the limit (never truncating silently); docs/limits.md lists them for users
// and must be updated with this file. Limits exist so a hostile or broken file cannot exhaust
// memory, hang the GPU or overflow the stack.
#pragma once

#include <cstdint>

namespace rmsc::limits {

// ---- Scene files (engine/scene/scene_json.cpp, json_parse.cpp) ----
constexpr std::uint64_t kSceneFileBytes = 64u << 20; // scene JSON text
constexpr int kSceneJsonDepth = 256;                 // nesting of JSON arrays and objects
constexpr int kSdfNodes = 100000;                    // nodes in the SDF tree (groups and shapes)
constexpr int kSdfGroupDepth = 128;                  // SDF groups nested in groups
constexpr int kLights = 16; // lights of a scene: "lights" plus glTF KHR_lights_punctual ones
constexpr int kMeshInstances = 4096;    // entries of "meshes"
constexpr int kMaterials = 4096;        // entries of "materials"
constexpr int kSdfMaterialTextures = 8; // distinct textures of the SDF materials
constexpr int kMarchSteps = 4096;       // "render.max_steps": bounds each GPU ray

// ---- Images and textures (glTF images, scene textures) ----
constexpr int kTextureDimension = 8192; // width and height, each, in pixels

// ---- Any input file read from disk (core/file_source.cpp) ----
constexpr std::uint64_t kInputFileBytes = std::uint64_t(1) << 30;

// ---- glTF files (engine/scene/gltf_*.cpp) ----
constexpr int kGltfJsonDepth = 128;                // checked before tinygltf parses it
constexpr int kGltfNodeDepth = 64;                 // node hierarchy depth
constexpr std::uint64_t kGltfVertices = 16u << 20; // per accessor and per asset
constexpr std::uint64_t kGltfIndices = 48u << 20;  // per accessor and per asset

} // namespace rmsc::limits
