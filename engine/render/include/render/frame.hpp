// Per-frame camera data shared by all passes: matrices, the frustum-corner matrix the march
// pass builds rays from, and the std140 uniform block that carries them
// (shaders/common/frame.glsl).
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>

namespace rmsc {

struct FrameCamera {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    // Columns: world-space directions from the eye through the bottom-left, bottom-right,
    // top-left and top-right corners of the image, scaled so their component along `forward`
    // is 1 (so t along an unnormalized corner ray is the view depth). Orthographic: all four
    // are `forward` (parallel rays).
    glm::mat4 frustumCorners{1.0f};
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    float nearPlane = 0.05f;
    float farPlane = 200.0f;
    // Orthographic: the rays start on the camera's plane, at position + sx * orthoRight +
    // sy * orthoUp for the image's -1..1 coordinates (sx, sy); both zero for a perspective view.
    bool orthographic = false;
    glm::vec3 orthoRight{0.0f}; // right, half the view's width long
    glm::vec3 orthoUp{0.0f};    // up, half its height long
};

FrameCamera makeFrameCamera(const Camera& camera, int width, int height);

// Direction (unnormalized, forward component 1) through pixel centre (x + 0.5, y + 0.5), with
// y counted from the bottom row, exactly as the march pass computes it.
glm::vec3 pixelRayDirection(const FrameCamera& camera, float x, float y, int width, int height);
// Where that pixel's ray starts: the eye, or (orthographic) its point of the camera's plane.
glm::vec3 pixelRayOrigin(const FrameCamera& camera, float x, float y, int width, int height);

// The cone of a tile of the cone pass (render/cone_pass.hpp): the tile of `tileSize` pixels a
// side whose bottom-left pixel is (tileX, tileY) * tileSize, y counted from the bottom row.
// `axis` is the unit ray through the tile's centre, `chord` the largest |u - axis| over the
// unit rays u through the tile's four corners, as shaders/passes/cone.frag computes them.
// Orthographic: a cylinder instead, from `origin` (the tile centre's ray origin) along the view,
// `chord` 0 and `radius` the tile's half diagonal in world units.
struct ConeTile {
    glm::vec3 axis{0.0f, 0.0f, -1.0f};
    float chord = 0.0f;
    glm::vec3 origin{0.0f};
    float radius = 0.0f;
};
ConeTile coneTile(const FrameCamera& camera, int tileX, int tileY, int tileSize, int width,
                  int height);

// std140 uniform block at binding 0, mirrored by FrameBlock in shaders/common/frame.glsl.
struct GpuFrame {
    glm::mat4 view;
    glm::mat4 viewProjection;
    glm::mat4 frustumCorners;
    glm::vec4 cameraPosition; // xyz, w = near plane
    glm::vec4 cameraForward;  // xyz, w = far plane
    glm::vec4 background;     // rgb = background colour, a = exposure
    glm::vec4 ambient;        // rgb = ambient light
    glm::vec4 march;          // x = max steps, y = max distance, z = surface epsilon,
                              // w = march relaxation (kSdfMarchRelaxation)
    glm::vec4 viewport;       // x = width, y = height, z = nearest SDF part, w = 1 for
                              // zero-to-one clip depth (host frames), else 0
    glm::vec4 sky;            // x = SkyType, y = intensity, z = image's top mip level, w = rotation
    glm::vec4 skyZenith;      // rgb = constant colour or gradient zenith
    glm::vec4 skyHorizon;     // rgb = gradient horizon
    glm::vec4 skyGround;      // rgb = gradient ground
    glm::vec4 fog;            // rgb = colour, a = density
    glm::vec4 shadow;         // x = SDF shadow steps (0 = off), y = min distance, z = max distance
    glm::vec4 shadowMap;      // x = map size, y = PCF radius, z = normal offset (texels)
    glm::vec4 ao;             // x = samples (0 = off), y = distance, z = strength, w = FXAA on
    glm::vec4 orthoRight;     // xyz = FrameCamera::orthoRight (0 for perspective)
    glm::vec4 orthoUp;        // xyz = FrameCamera::orthoUp, w = 1 for orthographic, else 0
};
static_assert(sizeof(GpuFrame) == 3 * 64 + 16 * 16);

// Fills the sky and fog fields of `frame` (imageLevels: mip levels of the sky image, 0 = none).
void packEnvironment(const Environment& environment, int imageLevels, GpuFrame& frame);

GpuFrame packFrame(const FrameCamera& camera, const RenderSettings& settings, int width,
                   int height);

} // namespace rmsc
