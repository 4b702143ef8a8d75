// A PreparedScene on the GPU: uploaded meshes, mesh instances, and the SSBOs (SDF program,
// materials, lights) every pass reads. Parameter edits update buffer contents only.
#pragma once

#include "gl/handles.hpp"
#include "prepare/prepared_scene.hpp"
#include "render/gpu_layout.hpp"
#include "render/gpu_mesh.hpp"
#include "render/sdf_program_buffer.hpp"
#include "render/shading_code.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/glsl_codegen.hpp"

#include <vector>

namespace rmsc {

struct GpuMeshInstance {
    int mesh = -1; // index into GpuScene::meshes
    glm::mat4 model{1.0f};
    glm::mat3 normalMatrix{1.0f};
    std::uint32_t objectId = 0;
    int materialOverride = -1; // index into PreparedScene::materials, or -1
};

// A shell (prepare/prepared_scene.hpp) on the GPU: its proxy mesh (object space), its frame and
// clip box, and the GLSL of its map ("generated/shell_map.glsl", functions shellSceneEmpty,
// shellDistance and shellSurface reading the program buffer from where the shell's
// instructions start).
struct GpuShell {
    gl::Buffer vertices; // vec3 positions
    gl::Buffer indices;
    gl::VertexArray vertexArray;
    GLsizei indexCount = 0;
    glm::mat4 objectToWorld{1.0f};
    glm::mat4 worldToObject{1.0f};
    float distanceScale = 1.0f;
    glm::vec3 clipMin{0.0f}; // object space
    glm::vec3 clipMax{0.0f};
    bool clipsContent = false; // PreparedShell::clipsContent
    std::string map;
};

struct GpuScene {
    std::vector<GpuMesh> meshes;
    std::vector<std::vector<MeshMaterial>> meshMaterials; // per mesh, from the glTF
    std::vector<GpuMeshInstance> instances;
    std::vector<Material> materials; // copy of PreparedScene::materials, for overrides
    SdfProgramBuffer sdfProgram;     // GpuSdfHeader + instructions
    gl::Buffer sdfData;              // SdfProgram::data (vec4[], at least one entry)
    // The Cells strategy's cell table and programs (GpuSdfCellHeader + SdfCellGrid::words),
    // none for the other strategies, and what building it measured.
    // Its header is kept for updateSdfCells; the buffer has room for a quarter more words.
    gl::Buffer sdfCells;
    gl::Texture sdfCellTexels; // the same storage as pairs of words (RG32UI, 8-byte texels)
    GpuSdfCellHeader sdfCellHeader;
    std::uint64_t sdfCellStamp = 0; // the pack it holds (SdfCellGrid::packStamp)
    SdfCellStats sdfCellStats;
    int sdfCellLevels = 0;
    gl::Buffer materialBuffer; // GpuMaterial[]
    gl::Buffer lightBuffer;    // GpuLightHeader + GpuLight[]
    // SDF material textures, one per PreparedScene::textures entry, bound to texture units
    // kSdfMaterialTextureFirstUnit + slot by bindBuffers.
    std::vector<gl::Texture> materialTextures;
    int sdfInstructionCount = 0;
    std::size_t sdfCodeCount = 0; // instructions in sdfProgram (the cells' code under Cells)
    std::size_t sdfDataCount = 0; // entries in sdfData
    SdfProgram sdf;     // the scene's program (not the shells'), kept for the interpreter's first
                        // guess of the nearest part (sdfNearestLeaf, per frame)
    std::string sdfMap; // GLSL of "generated/sdf_map.glsl" (sdf/glsl_codegen.hpp)
    // The shading code of the scene's own settings and materials (sceneShading): its
    // sdfTextures says whether any material has a texture.
    ShadingCode shading;
    std::vector<GpuShell> shells; // their instructions follow the scene's in sdfProgram

    // Lighting: the shadow-map views planned from the lights and the mesh bounds, the
    // environment and its sky image (RGB16F with mipmaps; levels 0 without an image sky).
    std::vector<GpuShadowView> shadowViews;
    gl::Buffer shadowViewBuffer; // GpuShadowView[] (one dummy entry when there are none)
    int shadowMapSize = 0;
    float shadowSlopeBias = 0.0f;
    Environment environment;
    gl::Texture skyImage;
    int skyLevels = 0;

    // Binds the SSBOs at their SsboBinding points, the uniform blocks over them (the program's
    // window, the cell header) and the SDF material and texel textures to their units.
    void bindBuffers() const;
};

// Makes `lights` the lights `gpu` is drawn with: its light buffer and its shadow-map views,
// planned against the scene's meshes and shells. uploadScene gives the prepared scene's own;
// a host may draw with its own (rmsc::api::Renderer::drawInto).
void setSceneLights(GpuScene& gpu, const PreparedScene& prepared, const std::vector<Light>& lights);

// The shading code of a frame of `prepared` drawn with its own render settings.
ShadingCode sceneShading(const PreparedScene& prepared);

// Under the Cells strategy the program is pruned here, unless `cells` gives the grid already
// pruned for prepared.sdf (the viewer's, pruned again after an edit: sdf/cell_pruning.hpp).
// `sdf`, when given, is drawn instead of prepared.sdf (the viewer's interpreter draws the same
// tree compiled with its bounding hierarchy).
GpuScene uploadScene(const PreparedScene& prepared, SdfStrategy strategy = SdfStrategy::Baked,
                     const SdfCellGrid* cells = nullptr, const SdfProgram* sdf = nullptr);

// Writes `grid` into gpu's cell buffer: when it was pruned again (repruneSdfCells) from the very
// grid the buffer holds (SdfCellGrid::changedSince is the buffer's pack), only the header and
// the words the re-prune changed; else all of them; a new buffer when they do not fit. The
// program buffer and whether every surface lies inside the grid (the header's info.w, a fact of
// the scene) are the caller's: updateSdfScene writes all three.
void updateSdfCells(GpuScene& gpu, const SdfCellGrid& grid);

// An edit of numbers drawn with the cells map, in place: writes `prepared` into gpu's buffers
// (the program with the cells' code, the SDF data, the materials, the lights) and `grid` into
// its cells (updateSdfCells), when gpu was uploaded with cells from a scene of the same shape
// (as many instructions, data entries and materials) and neither has meshes, shells, material
// textures or an image sky, and `grid` fits what gpu's map assumes of its lists (SdfCellFit:
// stacks no deeper than its variables hold). False, with nothing written, when it does not
// qualify: upload anew.
bool updateSdfScene(GpuScene& gpu, const PreparedScene& prepared, const SdfCellGrid& grid);

} // namespace rmsc
