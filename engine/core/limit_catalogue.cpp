// The limit catalogue's rows, and its text and markdown forms.
#include "core/limit_catalogue.hpp"

#include "core/limits.hpp"

#include <cstdint>

namespace rmsc {
namespace {

using namespace limits;

// Where the compiler refuses a tree over its limits.
constexpr const char* kAtTheTree = "refused at `/sdf` (for a shell, at its node)";
constexpr const char* kAtTheTreeNaming =
    "refused at `/sdf` (for a shell, at its node), naming the node where the tree first goes over";

// In the order docs/limits.md lists them: scene files, the compiled SDF tree, rendering, images,
// files, glTF, the command line.
constexpr Limit kLimits[] = {
    {"Scene file size", double(kSceneFileBytes), "bytes", "the scene JSON text",
     "refused at the file (`\"\"`)", "kSceneFileBytes"},
    {"JSON nesting", kSceneJsonDepth, "levels", "arrays and objects in a scene file",
     "refused at the too-deep value", "kSceneJsonDepth"},
    {"SDF nodes", kSdfNodes, "", "groups and shapes in `sdf`, counted in file order",
     "refused at the first node over the limit", "kSdfNodes"},
    {"SDF group nesting", kSdfGroupDepth, "levels", "groups in groups",
     "refused at the too-deep group", "kSdfGroupDepth"},
    {"Modifiers per node", kSdfModifiers, "", "entries of one node's `modifiers`",
     "refused at the node's `modifiers`", "kSdfModifiers"},
    {"Polar copies", kPolarCopies, "", "`count` of a `polar` modifier", "refused at the `count`",
     "kPolarCopies"},
    {"Repeat copies", kRepeatCopies, "per axis",
     "`count` of a `repeat` modifier, each axis (0 repeats without end)",
     "refused at the axis's `count` element", "kRepeatCopies"},
    {"Polygon points", kPolygonPoints, "", "`points` of one `polygon` profile (at least 3)",
     "refused at the profile's `points`", "kPolygonPoints"},
    {"Lights", kLights, "", "entries of `lights`, plus the glTF files' KHR_lights_punctual lights",
     "refused at `/lights`, or at the mesh instance that goes over", "kLights"},
    {"Mesh instances", kMeshInstances, "", "entries of `meshes`", "refused at `/meshes`",
     "kMeshInstances"},
    {"Materials", kMaterials, "", "entries of `materials`", "refused at `/materials`",
     "kMaterials"},
    {"SDF material textures", kSdfMaterialTextures, "",
     "distinct texture files the SDF materials use (a file used as base colour and as a linear "
     "map counts twice)",
     "refused at the texture over the limit", "kSdfMaterialTextures"},
    {"SDF material texels", double(kSdfTextureTexels), "texels",
     "decoded pixels of the SDF materials' textures together, from the image headers before "
     "decoding",
     "refused at the texture that goes over", "kSdfTextureTexels"},
    {"March steps", kMarchSteps, "",
     "`render.max_steps`: each GPU ray stops after this many steps, so no scene can hang the GPU",
     "refused at `/render/max_steps`", "kMarchSteps"},
    {"SDF instructions", kSdfInstructions, "",
     "what the SDF tree compiles to (about one instruction per shape, operation and modifier)",
     kAtTheTree, "kSdfInstructions"},
    {"SDF stack", kSdfStack, "entries",
     "the values the shader holds at once while it evaluates the tree (smooth operations and the "
     "first child of a subtraction keep their order: nest groups in their first child)",
     kAtTheTreeNaming, "kSdfStack"},
    {"SDF point stack", kSdfPointStack, "entries",
     "nesting of nodes with point modifiers or displacement, and of repetitions with the "
     "neighbour check",
     kAtTheTreeNaming, "kSdfPointStack"},
    {"Polygon points in all", kSdfData, "",
     "the points of every polygon profile of the SDF tree (the shader's data buffer)", kAtTheTree,
     "kSdfData"},
    {"Shapes in one shell", kShellShapes, "",
     "the shapes below a node marked `\"shell\"` (a shell's shader is always generated code, "
     "which costs compile time per shape)",
     "refused at the node's `shell` key", "kShellShapes"},
    {"Shapes drawn by generated code", kGeneratedCodeShapes, "",
     "the shapes of an SDF tree drawn by the baked or buffer strategy",
     "the tree is drawn by its per-cell programs instead (the `cells` strategy: no shader build "
     "that grows with the scene)",
     "kGeneratedCodeShapes"},
    {"Generated code statements", kGeneratedCodeStatements, "",
     "statements of the generated code of an SDF tree or a shell (about one per instruction, "
     "box tests left out); each costs the shader compiler time and memory at every place the "
     "shaders evaluate the map",
     "the tree is drawn by its per-cell programs instead; a shell over it is refused at its "
     "`shell` key",
     "kGeneratedCodeStatements"},
    {"SDF cost per pixel", double(kSdfPixelCost), "instructions",
     "the worst-case cost of one pixel's march: the costliest march step (every instruction "
     "run, neighbour checks and polar copies as emitted, a fractal one per iteration; under "
     "the cells strategy the longest cell program) times `render.max_steps`, the scene's shells "
     "added; a frame costs this times its pixels at most",
     "refused at the node that costs most, with the cost and the budget", "kSdfPixelCost"},
    {"Pruning cells", kSdfCells, "",
     "cells of the `cells` strategy's hierarchy (8 bytes each on the GPU, plus their programs)",
     "refinement stops: the cells near the surface are refined first, the rest keep their "
     "parents' programs",
     "kSdfCells"},
    {"Pruning levels", kSdfCellLevels, "levels",
     "4x4x4 subdivisions of the `cells` strategy's grid (the content's cube grown 16 times)",
     "fixed: the finest cells are the content's cube divided 256 times", "kSdfCellLevels"},
    {"Shadow maps", kShadowViews, "",
     "mesh shadow maps of a scene, in light order: one per directional or spot light, six per "
     "point light",
     "lights past the budget cast no mesh shadows", "kShadowViews"},
    {"Texture size", kTextureDimension, "pixels a side",
     "every image: glTF images and scene textures", "refused at the image", "kTextureDimension"},
    {"Any input file", double(kInputFileBytes), "bytes",
     "every file read from disk (scenes, glTF, buffers, images), checked before reading",
     "refused at the file", "kInputFileBytes"},
    {"glTF JSON nesting", kGltfJsonDepth, "levels", "checked before the glTF parser sees the text",
     "refused at the file", "kGltfJsonDepth"},
    {"glTF node depth", kGltfNodeDepth, "levels", "the node hierarchy (cycles are refused too)",
     "refused at the node", "kGltfNodeDepth"},
    {"glTF vertices", double(kGltfVertices), "",
     "per accessor, and per file after instancing, counted from the accessors before any is read",
     "refused at the accessor or node", "kGltfVertices"},
    {"glTF indices", double(kGltfIndices), "",
     "triangle indices per accessor, and per file after instancing (strips and fans counted as "
     "the triangle lists they become)",
     "refused at the accessor or node", "kGltfIndices"},
    {"glTF texels", double(kGltfTexels), "texels",
     "decoded pixels of one file's images (an image used by several textures, or listed twice "
     "with the same URI or buffer view, is decoded and counted once), from the image headers "
     "before decoding",
     "refused at the image that goes over", "kGltfTexels"},
    {"glTF buffer bytes", double(kGltfBufferBytes), "bytes",
     "the `byteLength` of every buffer of one file together (a file listed twice counts twice), "
     "before any is read",
     "refused at the buffer that goes over", "kGltfBufferBytes"},
    {"glTF morph targets", kGltfMorphTargets, "", "`targets` of one mesh primitive",
     "refused at the primitive's `targets`", "kGltfMorphTargets"},
    {"glTF skin joints", kGltfJoints, "", "`joints` of one skin", "refused at the skin's `joints`",
     "kGltfJoints"},
    {"glTF animation keys", double(kGltfAnimationKeys), "",
     "key times of all the animation samplers of one file together",
     "refused at the sampler's `input` that goes over", "kGltfAnimationKeys"},
    {"Scene glTF vertices", double(kSceneGltfVertices), "",
     "vertices of all the glTF files of a scene (meshes and shell proxies) after instancing, "
     "counted from the accessors before any is read",
     "refused at the node that goes over, in the file that goes over", "kSceneGltfVertices"},
    {"Scene glTF indices", double(kSceneGltfIndices), "",
     "triangle indices of all the glTF files of a scene after instancing",
     "refused at the node that goes over, in the file that goes over", "kSceneGltfIndices"},
    {"Scene texels", double(kSceneTexels), "texels",
     "decoded pixels of everything a scene shows: the images of all its glTF files, its "
     "material textures and its sky image, from the image headers before decoding",
     "refused at the image that goes over (in the file that goes over)", "kSceneTexels"},
    {"Messages per input", kDiagnosticsKept, "",
     "errors and warnings kept and printed for one input (every one is still counted)",
     "the rest are summed up as \"... and N more errors\"", "kDiagnosticsKept"},
    {"Image size", kImageSize, "pixels a side",
     "`--size` of `rmsc render`, `rmsc bench` and `rmsc view`", "refused (exit 2)", "kImageSize"},
    {"Image pixels", double(kImagePixels), "pixels",
     "`--size` width times height (a frame takes about 70 bytes of memory a pixel)",
     "refused (exit 2)", "kImagePixels"},
    {"Export voxels", double(kExportVoxels), "cells",
     "the grid `rmsc export` samples: the content's box (with two cells of margin, rounded up to "
     "blocks of 8) divided by the voxel size",
     "refused before sampling, with the grid's size", "kExportVoxels"},
    {"Export triangles", double(kExportTriangles), "",
     "the triangles `rmsc export` makes (as many as the glTF reader takes back), estimated from "
     "the blocks near the surface after one sample per block",
     "refused before the surface is extracted, with the estimate", "kExportTriangles"},
};

constexpr std::uint64_t kMi = std::uint64_t(1) << 20;
constexpr std::uint64_t kGi = std::uint64_t(1) << 30;

// Table cells must not contain a bare "|".
std::string cell(const char* text) {
    std::string out;
    for (const char* c = text; *c; ++c) {
        if (*c == '|') out += '\\';
        out += *c;
    }
    return out;
}

} // namespace

std::span<const Limit> limitCatalogue() {
    return kLimits;
}

std::string limitValueText(const Limit& limit) {
    const auto value = std::uint64_t(limit.value);
    const std::string digits = std::to_string(value);
    const std::string unit = limit.unit;
    if (unit == "bytes") {
        if (value % kGi == 0) return std::to_string(value / kGi) + " GiB (" + digits + " bytes)";
        if (value % kMi == 0) return std::to_string(value / kMi) + " MiB (" + digits + " bytes)";
        return digits + " bytes";
    }
    std::string out = digits;
    if (value >= kMi && value % kMi == 0) out += " (" + std::to_string(value / kMi) + " Mi)";
    if (!unit.empty()) out += " " + unit;
    return out;
}

std::string limitCatalogueMarkdown() {
    std::string out = "| Limit | Value | Applies to | When exceeded |\n"
                      "|---|---|---|---|\n";
    for (const Limit& limit : kLimits)
        out += "| " + cell(limit.name) + " | " + limitValueText(limit) + " | " +
               cell(limit.bounds) + " | " + cell(limit.exceeded) + " |\n";
    return out;
}

} // namespace rmsc
