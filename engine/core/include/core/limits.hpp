// Every hard limit of rmsc, in one place: sizes and counts of what it reads, and the fixed
// budgets of the shaders and the renderer. The readers refuse input over a limit with an error
// naming the limit (never truncating silently). Each constant has a row in the limit catalogue
// (core/limit_catalogue.hpp), which `rmsc limits` prints and docs/limits.md shows; a unit test
// fails when a constant here has no row. Limits exist so a hostile or broken file cannot
// exhaust memory, hang the GPU or overflow the stack.
#pragma once

#include <cstdint>

namespace rmsc::limits {

// ---- Scene files (engine/scene/scene_json.cpp, sdf_json.cpp, json_parse.cpp) ----
constexpr std::uint64_t kSceneFileBytes = 64u << 20; // scene JSON text
constexpr int kSceneJsonDepth = 256;                 // nesting of JSON arrays and objects
constexpr int kSdfNodes = 100000;                    // nodes in the SDF tree (groups and shapes)
constexpr int kSdfGroupDepth = 128;                  // SDF groups nested in groups
constexpr int kSdfModifiers = 16;                    // entries of one node's "modifiers"
constexpr int kPolarCopies = 1024;                   // "count" of a polar modifier
constexpr int kRepeatCopies = 1 << 20;               // "count" of a repeat modifier, per axis
constexpr int kPolygonPoints = 256;                  // "points" of one polygon profile
constexpr int kLights = 16; // lights of a scene: "lights" plus glTF KHR_lights_punctual ones
constexpr int kMeshInstances = 4096;    // entries of "meshes"
constexpr int kMaterials = 4096;        // entries of "materials"
constexpr int kSdfMaterialTextures = 8; // distinct textures of the SDF materials
constexpr int kMarchSteps = 4096;       // "render.max_steps": bounds each GPU ray

// ---- The compiled SDF tree (engine/sdf/compiler.cpp; the shader's fixed arrays) ----
// The same numbers are written in shaders/common/sdf_functions.glsl (SDF_MAX_STACK,
// SDF_MAX_POINT_STACK); sdf/program.hpp names them for the SDF code.
constexpr int kSdfInstructions = 1 << 16; // instructions one tree may compile to
constexpr int kSdfStack = 24;             // value stack of the GLSL interpreter
constexpr int kSdfPointStack = 16;        // point stack: how deep saved points may nest
constexpr int kSdfData = 1 << 16;         // entries of the SDF data buffer (polygon points)
constexpr int kShellShapes = 160;         // shapes in one shell (its map is generated code)
// Shapes of a tree drawn by generated code; above it the renderer draws the tree with the
// per-cell programs (generated code costs compile time in proportion to the scene).
constexpr int kGeneratedCodeShapes = 160;
// Statements of generated code (the baked and buffer strategies: about one per instruction,
// sdf/cost_model.hpp); above it the tree is drawn by its per-cell programs too, and a shell
// (always generated code) is refused.
constexpr int kGeneratedCodeStatements = 400;
// The worst-case cost of one pixel's march, in instructions (sdf/cost_model.hpp): the costliest
// march step (the longest cell program under the cells strategy) times render.max_steps.
constexpr std::int64_t kSdfPixelCost = std::int64_t(1) << 20;
// Cells of the per-cell pruning (sdf/cell_pruning.hpp) in all, and its levels.
constexpr int kSdfCells = 1 << 21;
constexpr int kSdfCellLevels = 6;

// ---- Rendering (engine/render) ----
constexpr int kShadowViews = 12; // shadow-map layers of a scene (a point light takes six)

// ---- Images and textures (glTF images, scene textures) ----
constexpr int kTextureDimension = 8192; // width and height, each, in pixels

// ---- The rmsc command (engine/app) ----
constexpr int kImageSize = 16384; // --size of render, bench and view, each side in pixels
// --size, width times height: a frame takes about 70 bytes of memory a pixel (G-buffers,
// readback; measured: 1.2 GiB peak for a 4096x4096 render on llvmpipe), so about 2.2 GiB here.
constexpr std::int64_t kImagePixels = std::int64_t(1) << 25;
// rmsc export: cells of the sampling grid (1024^3), and triangles of the mesh (what the glTF
// reader takes back: kGltfIndices / 3).
constexpr std::int64_t kExportVoxels = std::int64_t(1) << 30;
constexpr std::int64_t kExportTriangles = std::int64_t(16) << 20;

// ---- Any input file read from disk (core/file_source.cpp) ----
constexpr std::uint64_t kInputFileBytes = std::uint64_t(1) << 30;

// ---- glTF files (engine/scene/gltf_*.cpp) ----
constexpr int kGltfJsonDepth = 128;                // checked before tinygltf parses it
constexpr int kGltfNodeDepth = 64;                 // node hierarchy depth
constexpr std::uint64_t kGltfVertices = 16u << 20; // per accessor and per asset
constexpr std::uint64_t kGltfIndices = 48u << 20;  // per accessor and per asset
// The load budget, checked before anything is allocated: vertices and indices from the
// accessors' counts, texels from the image headers, buffer bytes from "byteLength".
constexpr std::uint64_t kGltfTexels = std::uint64_t(1) << 27;      // decoded, per file
constexpr std::uint64_t kGltfBufferBytes = std::uint64_t(1) << 30; // buffers of one file
// Morph targets of one primitive, joints of one skin, and animation keys of one file (the key
// times of all its animations' samplers together): posing costs vertices x (targets + joints).
constexpr int kGltfMorphTargets = 64;
constexpr int kGltfJoints = 256;
constexpr std::uint64_t kGltfAnimationKeys = 1u << 20;
// What the glTF files of one scene (meshes and shell proxies) may hold together.
constexpr std::uint64_t kSceneGltfVertices = 32u << 20;
constexpr std::uint64_t kSceneGltfIndices = 96u << 20;
// Decoded texels of everything a scene shows: its glTF files' images, its material textures
// and its sky image.
constexpr std::uint64_t kSceneTexels = std::uint64_t(1) << 28;
// Decoded texels of the SDF materials' textures together (scene/material_textures.hpp).
constexpr std::uint64_t kSdfTextureTexels = std::uint64_t(1) << 26;

// ---- Diagnostics (core/diagnostics.cpp) ----
// Problems kept and printed for one input; the rest are counted ("... and 5 more errors").
constexpr int kDiagnosticsKept = 100;

} // namespace rmsc::limits
