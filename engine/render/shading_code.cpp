// The shading code a frame's programs are built with (see render/shading_code.hpp).
#include "render/shading_code.hpp"

namespace rmsc {

ShadingCode shadingCode(const RenderSettings& settings, bool sdfTextures) {
    ShadingCode code;
    code.shadows = settings.shadows.enabled;
    code.ambientOcclusion = settings.ao.samples > 0;
    code.sdfTextures = sdfTextures;
    return code;
}

std::string shadingDefines(const ShadingCode& code) {
    std::string text =
        "// The shading code this program is built with (render/shading_code.hpp).\n";
    if (code.shadows) text += "#define SHADING_SHADOWS 1\n";
    if (code.ambientOcclusion) text += "#define SHADING_AMBIENT_OCCLUSION 1\n";
    if (code.sdfTextures) text += "#define SHADING_SDF_TEXTURES 1\n";
    return text;
}

} // namespace rmsc
