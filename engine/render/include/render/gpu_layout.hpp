// The std430 structs of the scene buffers shared by every pass (materials, lights), mirrored in
// shaders/common/scene_buffers.glsl, and the binding points of all shader storage buffers. The
// shaders get the numbers below from generated/constants.glsl (renderGlslConstants in
// render/shader_library.hpp), never by hand.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rmsc {

// SSBO binding points (the shaders' *_BINDING).
enum SsboBinding : unsigned {
    kSdfProgramBinding = 0,
    kMaterialBinding = 1,
    kLightBinding = 2,
    kShadowViewBinding = 3,
    kSdfDataBinding = 4,          // SdfProgram::data (shaders/common/sdf_scene.glsl)
    kMarchStatisticsBinding = 5,  // fragments that marched (shaders/common/march_statistics.glsl)
    kJointMatrixBinding = 7,      // a mesh's joint matrices (shaders/common/skinning.glsl)
    kFieldSampleStartBinding = 8, // lattice starts (shaders/passes/field_sample.comp)
    kFieldSampleDistanceBinding = 9, // and the distances it writes
};

// Uniform block binding points: the frame (shaders/common/frame.glsl), the program buffer's
// uniform window (kSdfUniformInstructions, shaders/common/sdf_functions.glsl) and the cell
// buffer's header (GpuSdfCellHeader, shaders/common/sdf_cells.glsl; its words are read through
// kSdfCellTexelUnit). llvmpipe loads a uniform block's numbers once for all pixels, a storage
// buffer's one pixel at a time: the header is read at every march step.
enum UboBinding : unsigned {
    kFrameBinding = 0,
    kSdfProgramUniformBinding = 1,
    kSdfCellHeaderBinding = 2
};

// Texture units of the lighting inputs every shading pass samples (shaders/common/sky.glsl,
// shadows.glsl); passes keep their own textures on lower units.
enum LightingTextureUnit : unsigned { kSkyImageUnit = 14, kShadowMapUnit = 15 };

// The texture units of the SDF program buffer's texels (render/sdf_program_buffer.hpp) and of
// the cell buffer's (GpuScene::sdfCellTexels): after every other unit, so the march pass samples
// 18 textures (Renderer::create checks the driver allows it; desktop drivers and llvmpipe
// allow 32).
enum SdfTexelUnit : unsigned { kSdfProgramTexelUnit = 16, kSdfCellTexelUnit = 17 };

// The header of the cell buffer (shaders/common/sdf_cells.glsl), before SdfCellGrid::words.
struct GpuSdfCellHeader {
    glm::vec4 originSize{0.0f}; // xyz = the grid cube's corner, w = its edge
    glm::uvec4 info{0u};        // x = levels, y = the outside list's offset, z = its length,
                                // w = 1 when every surface lies inside the grid's cube
    glm::vec4 floorMin{0.0f};   // a floor (render/gpu_scene.cpp, setCellFloor): box, w = drop
    glm::vec4 floorMax{0.0f};   // w: 1 the program's (SdfCellGrid::floor), + 2 the outside
                                // list's (outsideFloor), 0 none
    // The grid's planes (SdfCellGrid::planes; render/gpu_scene.cpp, setCellPlanes): each field
    // dot(xyz, p) + w, and their instructions, the top bit set when the plane leads the lists
    // (SdfCellPlane::leads); a plane not there has the field SDF_FAR and the instruction
    // 0xffffffff.
    glm::vec4 planeFields[4]{};
    glm::uvec4 planeInstructions{0xffffffffu};
    // Where every hit lies (render/gpu_scene.cpp, setHitEnd): a box that holds every point
    // whose field is at most hitEndMin.w (0: no such box), xyz its corners.
    glm::vec4 hitEndMin{0.0f};
    glm::vec4 hitEndMax{0.0f};
};
static_assert(sizeof(GpuSdfCellHeader) == 176); // sdf_cells.glsl: the words from texel 22

// GpuLight::directionType.w.
enum GpuLightType : int { kGpuDirectional = 0, kGpuPoint = 1, kGpuSpot = 2 };

// Texture units of the SDF material textures in the march pass (shaders/common/
// material_textures.glsl): texture slot i (MaterialTexture::image) is bound to unit
// kSdfMaterialTextureFirstUnit + i, for i < kMaxSdfMaterialTextures.
enum SdfMaterialTextureUnit : unsigned { kSdfMaterialTextureFirstUnit = 5 };

// One triplanar texture of a material (std430, 16 bytes).
struct GpuMaterialTexture {
    std::int32_t slot = -1; // texture slot (MaterialTexture::image), -1 = none
    float scale = 1.0f;     // repeats per local unit
    float sharpness = 4.0f; // triplanar blend exponent
    float strength = 1.0f;  // normal maps: x and y scale
};
static_assert(sizeof(GpuMaterialTexture) == 16);

struct GpuMaterial {
    glm::vec4 baseColorMetallic; // rgb = base colour (linear), a = metallic
    glm::vec4 emissiveRoughness; // rgb = emissive (linear), a = roughness
    GpuMaterialTexture baseColorTexture;
    GpuMaterialTexture normalTexture;
    GpuMaterialTexture roughnessTexture;
};
static_assert(sizeof(GpuMaterial) == 80);
static_assert(offsetof(GpuMaterial, baseColorTexture) == 32);
static_assert(offsetof(GpuMaterial, roughnessTexture) == 64);

struct GpuLight {
    glm::vec4 directionType;  // xyz = direction the light travels (normalized), w = GpuLightType
    glm::vec4 colorIntensity; // rgb = linear colour, a = intensity
    glm::vec4 positionRange;  // xyz = position (point, spot), w = range (0 = unlimited)
    // x, y = spot cone scale and offset (KHR_lights_punctual: attenuation =
    // saturate(cos(angle) * x + y)^2), z = SDF shadow softness w (0 = casts no shadows),
    // w = first shadow view (index into the shadow view buffer, -1 = none; points use 6)
    glm::vec4 spotShadow;
};
static_assert(sizeof(GpuLight) == 64);
static_assert(offsetof(GpuLight, colorIntensity) == 16);
static_assert(offsetof(GpuLight, positionRange) == 32);
static_assert(offsetof(GpuLight, spotShadow) == 48);

// One rendered shadow map: a layer of the shadow map array (the layer is the view's index).
struct GpuShadowView {
    glm::mat4 lightViewProjection; // world -> the light's clip space
    // x = world size of a texel (orthographic) or texel size per unit distance (perspective),
    // y = 1 for perspective views, z = layer
    glm::vec4 params;
};
static_assert(sizeof(GpuShadowView) == 80);

// Header of the light buffer, before the array.
struct GpuLightHeader {
    glm::uvec4 count; // x = number of lights
};

// The scene's materials followed by the default material (used where none is named); the
// default's index is scene.materials.size().
std::vector<GpuMaterial> packMaterials(const std::vector<Material>& materials);
// Lights without shadow views; `defaultSoftness` is used where a light sets none, and
// `shadowsEnabled` false (or a light's castShadows false) gives softness 0 (no SDF shadows).
std::vector<GpuLight> packLights(const std::vector<Light>& lights, bool shadowsEnabled = false,
                                 float defaultSoftness = 0.05f);
GpuMaterial packMaterial(const Material& m);

} // namespace rmsc
