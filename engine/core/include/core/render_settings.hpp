// The render settings of a scene (the "render" object of a scene file): marching, shading,
// shadows and ambient occlusion. Plain data shared by the SDF evaluator, the scene and the
// renderer.
#pragma once

#include <glm/glm.hpp>

namespace rmsc {

// Shadow quality (the "shadows" object of the render settings). Off unless the scene enables it.
struct ShadowSettings {
    bool enabled = false;
    int steps = 64;            // SDF shadow-march steps per light and pixel (capped at 256)
    float softness = 0.05f;    // SDF penumbra width factor w (Quilez: k = 1 / w)
    float minDistance = 0.01f; // SDF shadow march starts this far from the surface
    float maxDistance = 50.0f; // and gives up after this distance
    int mapSize = 1024;        // mesh shadow maps: texels a side (256..4096)
    int pcfRadius = 1;         // PCF kernel radius in texels (0..3)
    float normalOffset = 1.5f; // receiver offset along the normal, in shadow-map texels
    float slopeBias = 2.0f;    // depth bias of the shadow pass (polygon offset factor)
};

// Ambient occlusion from the SDF (the "ao" object of the render settings); 0 samples = off.
struct AoSettings {
    int samples = 0;       // samples along the normal (0..16)
    float distance = 0.3f; // the farthest sample, world units
    float strength = 1.0f; // 0 = no darkening
};

// Ray-marching and shading settings of a scene.
struct RenderSettings {
    int maxSteps = 256;            // march steps per ray
    float maxDistance = 100.0f;    // rays stop after this distance (world units)
    float surfaceEpsilon = 0.001f; // a ray hits when the distance falls below this (scaled by t)
    glm::vec3 background{0.02f, 0.025f, 0.03f}; // linear RGB where nothing is hit
    glm::vec3 ambient{0.03f};                   // constant ambient light, linear RGB
    float exposure = 1.0f;                      // multiplies HDR colour before tone mapping
    ShadowSettings shadows;
    AoSettings ao;
    bool fxaa = false; // FXAA in the post pass
};

} // namespace rmsc
