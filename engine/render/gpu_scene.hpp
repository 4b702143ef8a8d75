// A PreparedScene on the GPU: uploaded meshes, mesh instances, and the SSBOs (SDF program,
// materials, lights) every pass reads. Parameter edits update buffer contents only.
#pragma once

#include "gl/handles.hpp"
#include "render/gpu_mesh.hpp"
#include "scene/prepared_scene.hpp"

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
    gl::Buffer materialBuffer;       // GpuMaterial[]
    gl::Buffer lightBuffer;          // GpuLightHeader + GpuLight[]
    int sdfInstructionCount = 0;

    // Binds the SSBOs at their SsboBinding points.
    void bindBuffers() const;
};

GpuScene uploadScene(const PreparedScene& prepared);

} // namespace rmsc
