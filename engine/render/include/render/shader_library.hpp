// The renderer's shader files: the GLSL in shaders/ (embedded into the binary at build time)
// and the files generated from the C++ catalogues and constants.
#pragma once

#include "gl/shader_source.hpp"
#include "sdf/glsl_constants.hpp"

#include <vector>

namespace rmsc {

// Embedded shaders, "generated/constants.glsl" (glslConstantsHeader), "generated/primitives.glsl"
// (the full catalogue dispatch) and a default "generated/sdf_map.glsl" (the interpreter); the
// renderer replaces the map per scene.
ShaderFiles embeddedShaderFiles();

// The renderer's numbers the shaders use: buffer and uniform block bindings (SsboBinding,
// UboBinding), texture units (the lighting textures, the SDF material textures, the cone
// pass's target), the light and sky types and the cone pass's tile size.
std::vector<GlslConstant> renderGlslConstants();

// "generated/constants.glsl": sdfGlslConstants() and renderGlslConstants() as #defines.
std::string glslConstantsHeader();

} // namespace rmsc
