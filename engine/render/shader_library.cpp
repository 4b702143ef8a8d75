// The renderer's shader files: embedded GLSL plus what the catalogues generate.
#include "render/shader_library.hpp"

#include "core/embedded.hpp"
#include "sdf/primitives.hpp"

namespace rmsc {

// Generated at build time into the render library (cmake/embed_files.cmake).
std::span<const EmbeddedFile> embeddedShaders(); // paths like "common/lighting.glsl"

ShaderFiles embeddedShaderFiles() {
    ShaderFiles shaderFiles;
    for (const EmbeddedFile& file : embeddedShaders())
        shaderFiles.files.emplace(std::string(file.path), std::string(file.data));
    shaderFiles.files.emplace("generated/primitives.glsl", generateGlslDispatch());
    // Until a scene supplies its own map: the interpreter over every primitive.
    shaderFiles.files.emplace("generated/sdf_map.glsl",
                              "#include \"generated/primitives.glsl\"\n"
                              "#include \"common/sdf_interpreter.glsl\"\n");
    return shaderFiles;
}

} // namespace rmsc
