// Uploading a prepared scene: meshes once per file, instances with their matrices, SSBOs.
#include "render/gpu_scene.hpp"

#include "render/gpu_layout.hpp"

#include <cstring>

namespace rmsc {
namespace {

// A buffer holding `header` followed by `items` (std430: the header is 16 bytes).
template <class Header, class Item>
gl::Buffer createHeaderedBuffer(const Header& header, const std::vector<Item>& items) {
    static_assert(sizeof(Header) == 16);
    std::vector<unsigned char> bytes(sizeof(Header) + items.size() * sizeof(Item));
    std::memcpy(bytes.data(), &header, sizeof(Header));
    if (!items.empty())
        std::memcpy(bytes.data() + sizeof(Header), items.data(), items.size() * sizeof(Item));
    return gl::createBufferWithData(GLsizeiptr(bytes.size()), bytes.data());
}

} // namespace

void GpuScene::bindBuffers() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSdfProgramBinding, sdfProgram.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialBinding, materialBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightBinding, lightBuffer.id());
}

GpuScene uploadScene(const PreparedScene& prepared) {
    GpuScene gpu;
    for (const MeshAsset& asset : prepared.assets) {
        gpu.meshes.push_back(uploadMesh(asset));
        gpu.meshMaterials.push_back(asset.materials);
    }
    const Scene& scene = prepared.scene;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        GpuMeshInstance instance;
        instance.mesh = prepared.instanceAsset[i];
        instance.model = scene.meshes[i].transform.matrix();
        instance.normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.model)));
        instance.objectId = kMeshIdBase + std::uint32_t(i);
        instance.materialOverride = scene.meshes[i].materialOverride;
        gpu.instances.push_back(instance);
    }
    gpu.materials = prepared.materials;

    GpuSdfHeader sdfHeader;
    sdfHeader.instructionCount = std::uint32_t(prepared.sdf.instructions.size());
    sdfHeader.stackDepth = std::uint32_t(prepared.sdf.stackDepth);
    gpu.sdfProgram = createHeaderedBuffer(sdfHeader, prepared.sdf.instructions);
    gpu.sdfInstructionCount = int(prepared.sdf.instructions.size());

    const std::vector<GpuMaterial> materials = packMaterials(prepared.materials);
    gpu.materialBuffer = gl::createBufferWithData(
        GLsizeiptr(materials.size() * sizeof(GpuMaterial)), materials.data());

    const std::vector<GpuLight> lights = packLights(scene.lights);
    GpuLightHeader lightHeader{glm::uvec4(std::uint32_t(lights.size()), 0, 0, 0)};
    gpu.lightBuffer = createHeaderedBuffer(lightHeader, lights);
    return gpu;
}

} // namespace rmsc
