// The renderer's shader files: the GLSL in shaders/ (embedded into the binary at build time)
// and the files generated from the C++ catalogues.
#pragma once

#include "gl/shader_source.hpp"

namespace rmsc {

// Embedded shaders, "generated/primitives.glsl" (the full catalogue dispatch) and a default
// "generated/sdf_map.glsl" (the interpreter); the renderer replaces the map per scene.
ShaderFiles embeddedShaderFiles();

} // namespace rmsc
