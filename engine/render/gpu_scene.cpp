// Uploading a prepared scene: meshes once per file, instances with their matrices, SSBOs.
#include "render/gpu_scene.hpp"

#include "gpu_texture.hpp"
#include "render/gpu_layout.hpp"
#include "render/sdf_program_buffer.hpp"
#include "render/shadow_views.hpp"

#include <algorithm>
#include <cmath>

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

// The cells buffer: the header, the grid's words, then room for a quarter more words (an edit's
// new lists go after the old ones: updateSdfCells writes them in place), a whole number of
// 8-byte texels; and its texels (shaders/common/sdf_cells.glsl, sdfCellTexels).
void createCellBuffer(GpuScene& gpu, const GpuSdfCellHeader& header, const SdfCellGrid& grid) {
    const std::size_t wordBytes = grid.words.size() * sizeof(std::uint32_t);
    const std::size_t bytes = (sizeof header + wordBytes + wordBytes / 4 + 8 + 7) / 8 * 8;
    gpu.sdfCells = gl::createBufferWithData(GLsizeiptr(bytes), nullptr);
    glNamedBufferSubData(gpu.sdfCells.id(), 0, sizeof header, &header);
    glNamedBufferSubData(gpu.sdfCells.id(), sizeof header, GLsizeiptr(wordBytes),
                         grid.words.data());
    gpu.sdfCellTexels = gl::createTexture(GL_TEXTURE_BUFFER);
    glTextureBuffer(gpu.sdfCellTexels.id(), GL_RG32UI, gpu.sdfCells.id());
}

// Every surface of the scene inside the grid's cube (a scene without planes or infinite
// repetitions): marches end where their rays leave it (common/sdf_cells.glsl).
bool everySurfaceInside(const PreparedScene& prepared, const SdfCellGrid& grid) {
    const SdfBounds whole =
        prepared.scene.sdf ? sdfNodeBounds(*prepared.scene.sdf) : SdfBounds{false, {}, ""};
    return whole.bounded && !whole.box.empty() &&
           glm::all(glm::greaterThanEqual(whole.box.min, grid.origin)) &&
           glm::all(glm::lessThanEqual(whole.box.max, grid.origin + grid.size));
}

// The field level whose box (sdfNodeBoundsAtLevel) ends the march's rays where every surface
// lies inside the grid: the hit threshold, epsilon * max(t, 1), stays under it up to t = 100 at
// the default epsilon (RenderSettings::surfaceEpsilon, 0.001), so no hit lies outside that box.
// A larger level grows the box, a smaller one ends fewer rays there (sdf_cells.glsl, sdfHitEnd).
constexpr float kHitEndLevel = 0.1f;

// The box where every hit lies, when every surface lies inside the grid's cube: the scene's
// bounds at kHitEndLevel. A ray that passes the content ends there, not at the cube's far side
// (the cube is the content's grown 16 times: the 1,000 mixed shapes, which have no floor, took
// 8.9 march steps a pixel crossing it, 3.6 with this end).
void setHitEnd(GpuSdfCellHeader& header, const PreparedScene& prepared) {
    header.hitEndMin = header.hitEndMax = glm::vec4(0.0f);
    if (header.info.w == 0u || !prepared.scene.sdf) return;
    const SdfBounds box = sdfNodeBoundsAtLevel(*prepared.scene.sdf, kHitEndLevel);
    if (!box.bounded || box.box.empty()) return;
    header.hitEndMin = glm::vec4(box.box.min, kHitEndLevel);
    header.hitEndMax = glm::vec4(box.box.max, 0.0f);
}

// The grid's planes (SdfCellGrid::planes), each a field dot(xyz, p) + w.
static_assert(sizeof(GpuSdfCellHeader::planeFields) / sizeof(glm::vec4) == kSdfCellPlanes);
void setCellPlanes(GpuSdfCellHeader& header, const SdfCellGrid& grid) {
    for (int k = 0; k < kSdfCellPlanes; ++k) {
        const bool used = std::size_t(k) < grid.planes.size();
        header.planeFields[k] =
            used ? grid.planes[std::size_t(k)].field : glm::vec4(0.0f, 0.0f, 0.0f, kSdfFar);
        const SdfCellPlane* plane = used ? &grid.planes[std::size_t(k)] : nullptr;
        header.planeInstructions[k] =
            plane ? plane->instruction | (plane->leads ? 0x80000000u : 0u) : 0xffffffffu;
    }
}

// The program's floor, which far cells may take instead of their constant (w + 1), and the
// floor that stands outside the grid for what the outside list leaves out (w + 2): the same
// one when there are both (the root's; sdf_cells.glsl, sdfCellDistance).
void setCellFloor(GpuSdfCellHeader& header, const SdfCellGrid& grid) {
    const std::optional<SdfFieldFloor>& floor = grid.floor ? grid.floor : grid.outsideFloor;
    const float uses = (grid.floor ? 1.0f : 0.0f) + (grid.outsideFloor ? 2.0f : 0.0f);
    header.floorMin = floor ? glm::vec4(floor->box.min, floor->drop) : glm::vec4(0.0f);
    header.floorMax = floor ? glm::vec4(floor->box.max, uses) : glm::vec4(0.0f);
}

// The size of `buffer` (0 for none).
std::size_t bufferBytes(const gl::Buffer& buffer) {
    GLint64 bytes = 0;
    if (buffer.id() != 0) glGetNamedBufferParameteri64v(buffer.id(), GL_BUFFER_SIZE, &bytes);
    return std::size_t(bytes);
}

} // namespace

void updateSdfCells(GpuScene& gpu, const SdfCellGrid& grid) {
    GpuSdfCellHeader& header = gpu.sdfCellHeader;
    header.originSize = glm::vec4(grid.origin, grid.size);
    header.info = glm::uvec4(std::uint32_t(grid.levels), grid.outsideOffset, grid.outsideLength,
                             header.info.w);
    setCellFloor(header, grid);
    setCellPlanes(header, grid);
    gpu.sdfCellStats = grid.stats;
    gpu.sdfCellLevels = grid.levels;
    const std::size_t capacity = bufferBytes(gpu.sdfCells);
    const bool fromHeld = grid.changedSince != 0 && grid.changedSince == gpu.sdfCellStamp;
    gpu.sdfCellStamp = grid.packStamp;
    if (sizeof header + grid.words.size() * sizeof(std::uint32_t) > capacity) {
        createCellBuffer(gpu, header, grid);
        gpu.sdfCellStats.bytes = bufferBytes(gpu.sdfCells);
        return;
    }
    gpu.sdfCellStats.bytes = capacity;
    glNamedBufferSubData(gpu.sdfCells.id(), 0, sizeof header, &header);
    const std::vector<SdfWordRange> all{{0, std::uint32_t(grid.words.size())}};
    for (const SdfWordRange& range : fromHeld ? grid.changedWords : all)
        glNamedBufferSubData(
            gpu.sdfCells.id(), GLintptr(sizeof header + range.first * sizeof(std::uint32_t)),
            GLsizeiptr(range.count * sizeof(std::uint32_t)), grid.words.data() + range.first);
}

bool updateSdfScene(GpuScene& gpu, const PreparedScene& prepared, const SdfCellGrid& grid) {
    const Scene& scene = prepared.scene;
    const std::size_t dataCount = std::max<std::size_t>(prepared.sdf.data.size(), 1);
    if (gpu.sdfCells.id() == 0 || !prepared.assets.empty() || !prepared.shells.empty() ||
        !prepared.textures.empty() || !gpu.meshes.empty() || !gpu.shells.empty() ||
        !gpu.materialTextures.empty() || scene.environment.sky == SkyType::Image ||
        gpu.environment.sky == SkyType::Image || grid.code.size() != gpu.sdfCodeCount ||
        dataCount != gpu.sdfDataCount || prepared.materials.size() != gpu.materials.size() ||
        prepared.sdf.instructions.size() != std::size_t(gpu.sdfInstructionCount))
        return false;
    // A grid deeper than the drawn map's stack variables (an edit moved shapes together) needs
    // the map for it: the variables would lose stack entries.
    if (sdfMapCellFit(gpu.sdfMap).shallowStacks && !sdfCellFit(grid).shallowStacks) return false;
    GpuSdfHeader sdfHeader;
    sdfHeader.instructionCount = std::uint32_t(prepared.sdf.instructions.size());
    sdfHeader.stackDepth = std::uint32_t(prepared.sdf.stackDepth);
    sdfHeader.pointStackDepth = std::uint32_t(prepared.sdf.pointStackDepth);
    sdfHeader.dataCount = std::uint32_t(dataCount);
    glNamedBufferSubData(gpu.sdfProgram.buffer.id(), 0, sizeof sdfHeader, &sdfHeader);
    glNamedBufferSubData(gpu.sdfProgram.buffer.id(), sizeof sdfHeader,
                         GLsizeiptr(grid.code.size() * sizeof(GpuSdfInstruction)),
                         grid.code.data());
    if (!prepared.sdf.data.empty())
        glNamedBufferSubData(gpu.sdfData.id(), 0,
                             GLsizeiptr(prepared.sdf.data.size() * sizeof(glm::vec4)),
                             prepared.sdf.data.data());
    const std::vector<GpuMaterial> materials = packMaterials(prepared.materials);
    glNamedBufferSubData(gpu.materialBuffer.id(), 0,
                         GLsizeiptr(materials.size() * sizeof(GpuMaterial)), materials.data());
    gpu.materials = prepared.materials;
    gpu.shading = sceneShading(prepared);
    setSceneLights(gpu, prepared, prepared.lights.empty() ? scene.lights : prepared.lights);
    gpu.environment = scene.environment;
    gpu.sdf = prepared.sdf;
    gpu.sdfCellHeader.info.w = everySurfaceInside(prepared, grid) ? 1u : 0u;
    setHitEnd(gpu.sdfCellHeader, prepared);
    updateSdfCells(gpu, grid);
    return true;
}

void GpuScene::bindBuffers() const {
    bindSdfProgramBuffer(sdfProgram);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialBinding, materialBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightBinding, lightBuffer.id());
    for (std::size_t i = 0; i < materialTextures.size(); ++i)
        glBindTextureUnit(kSdfMaterialTextureFirstUnit + GLuint(i), materialTextures[i].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowViewBinding, shadowViewBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSdfDataBinding, sdfData.id());
    if (sdfCells.id() != 0) {
        glBindBufferRange(GL_UNIFORM_BUFFER, kSdfCellHeaderBinding, sdfCells.id(), 0,
                          sizeof(GpuSdfCellHeader));
        glBindTextureUnit(kSdfCellTexelUnit, sdfCellTexels.id());
    }
}

void setSceneLights(GpuScene& gpu, const PreparedScene& prepared,
                    const std::vector<Light>& lights) {
    const ShadowSettings& shadows = prepared.scene.render.shadows;
    CasterBounds casters;
    for (const GpuMeshInstance& instance : gpu.instances) {
        if (instance.mesh < 0) continue;
        const MeshAsset& asset = prepared.assets[std::size_t(instance.mesh)];
        if (asset.primitives.empty()) continue;
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner(c & 1 ? asset.boundsMax.x : asset.boundsMin.x,
                                   c & 2 ? asset.boundsMax.y : asset.boundsMin.y,
                                   c & 4 ? asset.boundsMax.z : asset.boundsMin.z);
            casters.add(glm::vec3(instance.model * glm::vec4(corner, 1.0f)));
        }
    }
    for (const PreparedShell& shell : prepared.shells)
        for (const glm::vec3& corner : shell.proxy.positions)
            casters.add(glm::vec3(shell.compiled.objectToWorld * glm::vec4(corner, 1.0f)));
    const ShadowViewPlan plan = planShadowViews(lights, casters, shadows);
    std::vector<GpuLight> packed = packLights(lights, shadows.enabled, shadows.softness);
    for (std::size_t i = 0; i < packed.size(); ++i)
        packed[i].spotShadow.w = float(plan.firstView[i]);
    GpuLightHeader lightHeader{glm::uvec4(std::uint32_t(packed.size()), 0, 0, 0)};
    gpu.lightBuffer = createHeaderedBuffer(lightHeader, packed);
    gpu.shadowViews = plan.views;
    std::vector<GpuShadowView> views = plan.views;
    if (views.empty()) views.push_back(GpuShadowView{}); // a buffer is never empty
    gpu.shadowViewBuffer =
        gl::createBufferWithData(GLsizeiptr(views.size() * sizeof(GpuShadowView)), views.data());
    gpu.shadowMapSize = plan.views.empty() ? 0 : std::clamp(shadows.mapSize, 1, 4096);
    gpu.shadowSlopeBias = shadows.slopeBias;
}

ShadingCode sceneShading(const PreparedScene& prepared) {
    // (The images of the materials' textures, loaded: what SDF surfaces draw.)
    return shadingCode(prepared.scene.render, !prepared.textures.empty());
}

GpuScene uploadScene(const PreparedScene& prepared, SdfStrategy strategy, const SdfCellGrid* cells,
                     const SdfProgram* sdf) {
    const SdfProgram& drawn = sdf ? *sdf : prepared.sdf;
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
    gpu.shading = sceneShading(prepared);

    // The program buffer holds the scene's instructions, then each shell's; the data buffer the
    // same, with the shells' profile instructions pointing at their data's new place.
    // The Cells strategy: the program pruned per cell, whose instructions (the program's and
    // the few the pruning adds) are the scene's in the buffer.
    const bool pruned = effectiveSdfStrategy(drawn, strategy) == SdfStrategy::Cells;
    // The grid given, or the one the cost check (prepare/sdf_cost.hpp) pruned for this program.
    const std::vector<GpuSdfInstruction>& code = drawn.instructions;
    const bool costed = !cells && prepared.sdfCells &&
                        prepared.sdfCells->code.size() >= code.size() &&
                        std::memcmp(prepared.sdfCells->code.data(), code.data(),
                                    code.size() * sizeof(GpuSdfInstruction)) == 0;
    SdfCellGrid built;
    if (pruned && !cells && !costed)
        built =
            buildSdfCells(drawn, prepared.scene.sdf ? sdfContentBox(*prepared.scene.sdf) : Aabb{});
    const SdfCellGrid& grid = cells ? *cells : costed ? *prepared.sdfCells : built;
    const std::vector<GpuSdfInstruction>& sceneCode = pruned ? grid.code : drawn.instructions;
    std::vector<GpuSdfInstruction> shellCode; // after the scene's, in the same buffer
    std::vector<glm::vec4> sdfData = drawn.data;
    for (const PreparedShell& shell : prepared.shells) {
        SdfProgram program = shell.compiled.program;
        const float dataBase = float(sdfData.size());
        for (GpuSdfInstruction& in : program.instructions)
            if (SdfOpcode(in.opcode) == SdfOpcode::Profile) in.params[2].x += dataBase;
        sdfData.insert(sdfData.end(), program.data.begin(), program.data.end());
        GpuShell gpuShell;
        gpuShell.map =
            generateSdfMap(program, strategy, {"shell", sceneCode.size() + shellCode.size()});
        shellCode.insert(shellCode.end(), program.instructions.begin(), program.instructions.end());
        gpuShell.objectToWorld = shell.compiled.objectToWorld;
        gpuShell.worldToObject = shell.compiled.worldToObject;
        gpuShell.distanceScale = shell.compiled.distanceScale;
        gpuShell.clipMin = shell.clipMin;
        gpuShell.clipMax = shell.clipMax;
        gpuShell.clipsContent = shell.clipsContent;
        const ShellProxyMesh& proxy = shell.proxy;
        gpuShell.vertices = gl::createBufferWithData(
            GLsizeiptr(proxy.positions.size() * sizeof(glm::vec3)), proxy.positions.data());
        gpuShell.indices = gl::createBufferWithData(
            GLsizeiptr(proxy.indices.size() * sizeof(std::uint32_t)), proxy.indices.data());
        gpuShell.indexCount = GLsizei(proxy.indices.size());
        gpuShell.vertexArray = gl::createVertexArray();
        const GLuint vao = gpuShell.vertexArray.id();
        glVertexArrayVertexBuffer(vao, 0, gpuShell.vertices.id(), 0, sizeof(glm::vec3));
        glVertexArrayElementBuffer(vao, gpuShell.indices.id());
        glEnableVertexArrayAttrib(vao, 0);
        glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, 0, 0);
        gpu.shells.push_back(std::move(gpuShell));
    }
    GpuSdfHeader sdfHeader;
    sdfHeader.instructionCount = std::uint32_t(drawn.instructions.size());
    sdfHeader.stackDepth = std::uint32_t(drawn.stackDepth);
    sdfHeader.pointStackDepth = std::uint32_t(drawn.pointStackDepth);
    sdfHeader.dataCount = std::uint32_t(sdfData.size());
    if (sdfData.empty()) sdfData.emplace_back(0.0f); // a buffer is never empty
    gpu.sdfData =
        gl::createBufferWithData(GLsizeiptr(sdfData.size() * sizeof(glm::vec4)), sdfData.data());
    gpu.sdfProgram = createSdfProgramBuffer(sdfHeader, sceneCode, shellCode);
    gpu.sdfMap = generateSdfMap(drawn, strategy, {}, {}, pruned ? sdfCellFit(grid) : SdfCellFit{});
    if (pruned) {
        GpuSdfCellHeader header;
        header.originSize = glm::vec4(grid.origin, grid.size);
        header.info = glm::uvec4(std::uint32_t(grid.levels), grid.outsideOffset, grid.outsideLength,
                                 everySurfaceInside(prepared, grid) ? 1u : 0u);
        setHitEnd(header, prepared);
        setCellFloor(header, grid);
        setCellPlanes(header, grid);
        gpu.sdfCellHeader = header;
        createCellBuffer(gpu, header, grid);
        gpu.sdfCellStamp = grid.packStamp;
        gpu.sdfCellStats = grid.stats;
        gpu.sdfCellStats.bytes = bufferBytes(gpu.sdfCells);
        gpu.sdfCellLevels = grid.levels;
    }
    gpu.sdfInstructionCount = int(drawn.instructions.size());
    gpu.sdfCodeCount = sceneCode.size() + shellCode.size();
    gpu.sdfDataCount = sdfData.size();
    gpu.sdf = drawn;

    const std::vector<GpuMaterial> materials = packMaterials(prepared.materials);
    for (const TextureImage& texture : prepared.textures)
        gpu.materialTextures.push_back(uploadTexture(texture.image, texture.srgb));
    gpu.materialBuffer = gl::createBufferWithData(
        GLsizeiptr(materials.size() * sizeof(GpuMaterial)), materials.data());

    // Lights from the file and the glTF files (PreparedScene::lights); scenes prepared in code
    // without them use the file's.
    setSceneLights(gpu, prepared, prepared.lights.empty() ? scene.lights : prepared.lights);

    gpu.environment = scene.environment;
    const SkyImage& sky = prepared.skyImage;
    if (scene.environment.sky == SkyType::Image && sky.width > 0 && sky.height > 0) {
        gpu.skyLevels = 1 + int(std::floor(std::log2(double(std::max(sky.width, sky.height)))));
        gpu.skyImage = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(gpu.skyImage.id(), gpu.skyLevels, GL_RGB16F, sky.width, sky.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(gpu.skyImage.id(), 0, 0, 0, sky.width, sky.height, GL_RGB, GL_FLOAT,
                            sky.rgb.data());
        glGenerateTextureMipmap(gpu.skyImage.id());
        glTextureParameteri(gpu.skyImage.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(gpu.skyImage.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(gpu.skyImage.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(gpu.skyImage.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    return gpu;
}

} // namespace rmsc
