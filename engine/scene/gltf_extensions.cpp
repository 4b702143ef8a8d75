// The table of supported glTF extensions (see gltf_extensions.hpp).
#include "scene/gltf_extensions.hpp"

#include <array>

namespace rmsc {

namespace {

constexpr std::array kExtensions{
    GltfExtensionInfo{"KHR_lights_punctual",
                      "directional, point and spot lights, placed by their nodes"},
    GltfExtensionInfo{"KHR_materials_emissive_strength", "multiplies the emissive factor"},
    GltfExtensionInfo{"KHR_materials_unlit",
                      "the base colour (factor, texture, vertex colour) drawn without lighting"},
    GltfExtensionInfo{"KHR_mesh_quantization",
                      "integer and normalized integer positions, normals, tangents and "
                      "texture coordinates"},
    GltfExtensionInfo{"KHR_texture_transform",
                      "offset, rotation, scale and texCoord of every texture of a material"},
};

} // namespace

std::span<const GltfExtensionInfo> gltfExtensions() {
    return kExtensions;
}

bool gltfExtensionSupported(std::string_view name) {
    for (const GltfExtensionInfo& e : kExtensions)
        if (e.name == name) return true;
    return false;
}

} // namespace rmsc
