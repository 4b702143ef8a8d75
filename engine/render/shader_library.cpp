// The renderer's shader files: embedded GLSL plus what the catalogues and constants generate.
#include "render/shader_library.hpp"

#include "core/embedded.hpp"
#include "render/cone_pass.hpp"
#include "render/gpu_layout.hpp"
#include "render/shading_code.hpp"
#include "scene/material_textures.hpp"
#include "sdf/primitives.hpp"

namespace rmsc {

// Generated at build time into the render library (cmake/embed_files.cmake).
std::span<const EmbeddedFile> embeddedShaders(); // paths like "common/lighting.glsl"

std::vector<GlslConstant> renderGlslConstants() {
    const auto unit = [](unsigned value) { return glslInt(int(value)); };
    return {
        {"SDF_PROGRAM_BINDING", unit(kSdfProgramBinding)},
        {"MATERIAL_BINDING", unit(kMaterialBinding)},
        {"LIGHT_BINDING", unit(kLightBinding)},
        {"SHADOW_VIEW_BINDING", unit(kShadowViewBinding)},
        {"SDF_DATA_BINDING", unit(kSdfDataBinding)},
        {"MARCH_STATISTICS_BINDING", unit(kMarchStatisticsBinding)},
        {"JOINT_MATRIX_BINDING", unit(kJointMatrixBinding)},
        {"FIELD_SAMPLE_START_BINDING", unit(kFieldSampleStartBinding)},
        {"FIELD_SAMPLE_DISTANCE_BINDING", unit(kFieldSampleDistanceBinding)},
        {"FRAME_BINDING", unit(kFrameBinding)},
        {"SDF_PROGRAM_UNIFORM_BINDING", unit(kSdfProgramUniformBinding)},
        {"SDF_CELL_HEADER_BINDING", unit(kSdfCellHeaderBinding)},
        {"SKY_IMAGE_UNIT", unit(kSkyImageUnit)},
        {"SHADOW_MAP_UNIT", unit(kShadowMapUnit)},
        {"SDF_PROGRAM_TEXEL_UNIT", unit(kSdfProgramTexelUnit)},
        {"SDF_CELL_TEXEL_UNIT", unit(kSdfCellTexelUnit)},
        {"SDF_TEXTURE_FIRST_UNIT", unit(kSdfMaterialTextureFirstUnit)},
        {"SDF_TEXTURE_COUNT", glslInt(kMaxSdfMaterialTextures)},
        {"CONE_START_UNIT", unit(kConeStartUnit)},
        {"CONE_TILE_SIZE", glslInt(kConeTileSize)},
        {"LIGHT_DIRECTIONAL", glslInt(kGpuDirectional)},
        {"LIGHT_POINT", glslInt(kGpuPoint)},
        {"LIGHT_SPOT", glslInt(kGpuSpot)},
        {"SKY_NONE", glslInt(int(SkyType::None))},
        {"SKY_CONSTANT", glslInt(int(SkyType::Constant))},
        {"SKY_GRADIENT", glslInt(int(SkyType::Gradient))},
        {"SKY_IMAGE", glslInt(int(SkyType::Image))},
    };
}

std::string glslConstantsHeader() {
    return "// Generated from the C++ enums and constants (sdf/glsl_constants.hpp,\n"
           "// render/shader_library.hpp); do not edit.\n" +
           glslDefines(sdfGlslConstants()) + glslDefines(renderGlslConstants());
}

ShaderFiles embeddedShaderFiles() {
    ShaderFiles shaderFiles;
    for (const EmbeddedFile& file : embeddedShaders())
        shaderFiles.files.emplace(std::string(file.path), std::string(file.data));
    shaderFiles.files.emplace("generated/constants.glsl", glslConstantsHeader());
    shaderFiles.files.emplace("generated/primitives.glsl", generateGlslDispatch());
    // Until a scene supplies its own map: the interpreter over every primitive.
    shaderFiles.files.emplace("generated/sdf_map.glsl",
                              "#include \"generated/primitives.glsl\"\n"
                              "#include \"common/sdf_interpreter.glsl\"\n");
    // Until a scene supplies its own: every optional part of the shading code.
    shaderFiles.files.emplace("generated/shading.glsl", shadingDefines(ShadingCode{}));
    return shaderFiles;
}

} // namespace rmsc
