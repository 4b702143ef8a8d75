// Materials: glTF-style metallic-roughness values and the triplanar image textures of SDF
// shapes. Plain data shared by the SDF evaluator, the scene and the renderer.
#pragma once

#include <glm/glm.hpp>

#include <filesystem>
#include <string>

namespace rmsc {

// An image file mapped onto SDF shapes by triplanar projection in the shape's local space
// (so it moves with the shape). An empty `file` means no texture.
struct MaterialTexture {
    std::string file;           // as written in the scene file
    std::filesystem::path path; // resolved against the scene file's folder
    float scale = 1.0f;         // repeats per local unit
    float sharpness = 4.0f;     // exponent of the triplanar blend weights |n|^sharpness
    float strength = 1.0f;      // normal maps: scales the map's x and y
    std::string pointer;        // JSON pointer of the file name, for messages
    int image = -1;             // index into PreparedScene::textures, set by prepareScene

    bool present() const { return !file.empty(); }
};

// glTF-style metallic-roughness material.
struct Material {
    std::string name;
    glm::vec3 baseColor{0.8f}; // linear RGB
    float metallic = 0.0f;
    float roughness = 0.5f;
    glm::vec3 emissive{0.0f}; // linear RGB, added to the shaded colour
    // SDF shapes only (meshes use their glTF textures):
    MaterialTexture baseColorTexture; // sRGB; multiplies baseColor
    MaterialTexture normalTexture;    // linear, tangent-space normal map (+y up the image)
    MaterialTexture roughnessTexture; // linear; green channel multiplies roughness
};

} // namespace rmsc
