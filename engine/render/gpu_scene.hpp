// A PreparedScene on the GPU: uploaded meshes, mesh instances, and the SSBOs (SDF program,
// materials, lights) every pass reads. Parameter edits update buffer contents only.
#pragma once

#include "gl/handles.hpp"
#include "render/gpu_layout.hpp"
#include "render/gpu_mesh.hpp"
#include "scene/prepared_scene.hpp"
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

struct GpuScene {
    std::vector<GpuMesh> meshes;
    std::vector<std::vector<MeshMaterial>> meshMaterials; // per mesh, from the glTF
    std::vector<GpuMeshInstance> instances;
    std::vector<Material> materials; // copy of PreparedScene::materials, for overrides
    gl::Buffer sdfProgram;           // GpuSdfHeader + instructions
    gl::Buffer sdfData;              // SdfProgram::data (vec4[], at least one entry)
    gl::Buffer materialBuffer;       // GpuMaterial[]
    gl::Buffer lightBuffer;          // GpuLightHeader + GpuLight[]
    // SDF material textures, one per PreparedScene::textures entry, bound to texture units
    // kSdfMaterialTextureFirstUnit + slot by bindBuffers.
    std::vector<gl::Texture> materialTextures;
    int sdfInstructionCount = 0;
    std::string sdfMap; // GLSL of "generated/sdf_map.glsl" (sdf/glsl_codegen.hpp)

    // Lighting: the shadow-map views planned from the lights and the mesh bounds, the
    // environment and its sky image (RGB16F with mipmaps; levels 0 without an image sky).
    std::vector<GpuShadowView> shadowViews;
    gl::Buffer shadowViewBuffer; // GpuShadowView[] (one dummy entry when there are none)
    int shadowMapSize = 0;
    float shadowSlopeBias = 0.0f;
    Environment environment;
    gl::Texture skyImage;
    int skyLevels = 0;

    // Binds the SSBOs at their SsboBinding points and the SDF material textures to their units.
    void bindBuffers() const;
};

GpuScene uploadScene(const PreparedScene& prepared, SdfStrategy strategy = SdfStrategy::Baked);

} // namespace rmsc
