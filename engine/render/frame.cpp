// Camera matrices and the frustum-corner matrix.
#include "render/frame.hpp"

#include "sdf/cpu_eval.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace rmsc {

FrameCamera makeFrameCamera(const Camera& camera, int width, int height) {
    FrameCamera frame;
    const float aspect = float(width) / float(std::max(height, 1));
    frame.view = glm::lookAt(camera.position, camera.target, camera.up);
    frame.position = camera.position;
    frame.forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(frame.forward, camera.up));
    const glm::vec3 up = glm::cross(right, frame.forward);
    frame.nearPlane = camera.nearPlane;
    frame.farPlane = camera.farPlane;
    if (camera.projection == CameraProjection::Orthographic) {
        // Parallel rays along `forward`, each from its point of the camera's plane.
        const float halfHeight = 0.5f * camera.orthoHeight;
        const float halfWidth = halfHeight * aspect;
        frame.projection = glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight,
                                      camera.nearPlane, camera.farPlane);
        frame.viewProjection = frame.projection * frame.view;
        const glm::vec4 along(frame.forward, 0.0f);
        frame.frustumCorners = glm::mat4(along, along, along, along);
        frame.orthographic = true;
        frame.orthoRight = right * halfWidth;
        frame.orthoUp = up * halfHeight;
        return frame;
    }
    const float fovY = glm::radians(camera.fovYDegrees);
    frame.projection = glm::perspective(fovY, aspect, camera.nearPlane, camera.farPlane);
    frame.viewProjection = frame.projection * frame.view;
    const float tanY = std::tan(0.5f * fovY);
    const float tanX = tanY * aspect;
    auto corner = [&](float sx, float sy) {
        return glm::vec4(frame.forward + sx * tanX * right + sy * tanY * up, 0.0f);
    };
    frame.frustumCorners = glm::mat4(corner(-1, -1), corner(1, -1), corner(-1, 1), corner(1, 1));
    return frame;
}

glm::vec3 pixelRayDirection(const FrameCamera& camera, float x, float y, int width, int height) {
    const float u = (x + 0.5f) / float(width);
    const float v = (y + 0.5f) / float(height);
    const glm::mat4& c = camera.frustumCorners;
    const glm::vec3 bottom = glm::mix(glm::vec3(c[0]), glm::vec3(c[1]), u);
    const glm::vec3 top = glm::mix(glm::vec3(c[2]), glm::vec3(c[3]), u);
    return glm::mix(bottom, top, v);
}

glm::vec3 pixelRayOrigin(const FrameCamera& camera, float x, float y, int width, int height) {
    if (!camera.orthographic) return camera.position;
    const float sx = (x + 0.5f) / float(width) * 2.0f - 1.0f;
    const float sy = (y + 0.5f) / float(height) * 2.0f - 1.0f;
    return camera.position + sx * camera.orthoRight + sy * camera.orthoUp;
}

ConeTile coneTile(const FrameCamera& camera, int tileX, int tileY, int tileSize, int width,
                  int height) {
    if (camera.orthographic) {
        // As shaders/passes/cone.frag: the cylinder of the tile's parallel rays.
        ConeTile tile;
        tile.axis = camera.forward;
        const float centre = 0.5f * float(tileSize);
        tile.origin = pixelRayOrigin(camera, float(tileX * tileSize) + centre - 0.5f,
                                     float(tileY * tileSize) + centre - 0.5f, width, height);
        const glm::vec2 pixel(2.0f * glm::length(camera.orthoRight) / float(width),
                              2.0f * glm::length(camera.orthoUp) / float(height));
        tile.radius = 0.5f * float(tileSize) * glm::length(pixel);
        return tile;
    }
    // pixelRayDirection takes pixel indices; a window position p is pixel p - 0.5.
    auto unitRay = [&](float windowX, float windowY) {
        return glm::normalize(
            pixelRayDirection(camera, windowX - 0.5f, windowY - 0.5f, width, height));
    };
    const float x0 = float(tileX * tileSize);
    const float y0 = float(tileY * tileSize);
    const float size = float(tileSize);
    ConeTile tile;
    tile.axis = unitRay(x0 + 0.5f * size, y0 + 0.5f * size);
    for (int corner = 0; corner < 4; ++corner)
        tile.chord = std::max(tile.chord, glm::length(unitRay(x0 + float(corner & 1) * size,
                                                              y0 + float(corner >> 1) * size) -
                                                      tile.axis));
    return tile;
}

GpuFrame packFrame(const FrameCamera& camera, const RenderSettings& settings, int width,
                   int height) {
    GpuFrame frame{};
    frame.view = camera.view;
    frame.viewProjection = camera.viewProjection;
    frame.frustumCorners = camera.frustumCorners;
    frame.cameraPosition = glm::vec4(camera.position, camera.nearPlane);
    frame.cameraForward = glm::vec4(camera.forward, camera.farPlane);
    frame.background = glm::vec4(settings.background, settings.exposure);
    frame.ambient = glm::vec4(settings.ambient, 0.0f);
    frame.march = glm::vec4(float(settings.maxSteps), settings.maxDistance, settings.surfaceEpsilon,
                            kSdfMarchRelaxation);
    frame.viewport = glm::vec4(float(width), float(height), 0.0f, 0.0f);
    const ShadowSettings& shadows = settings.shadows;
    frame.shadow =
        glm::vec4(shadows.enabled ? float(std::clamp(shadows.steps, 1, 256)) : 0.0f,
                  shadows.minDistance, std::min(shadows.maxDistance, settings.maxDistance), 0.0f);
    frame.shadowMap =
        glm::vec4(shadows.enabled ? float(shadows.mapSize) : 0.0f,
                  float(std::clamp(shadows.pcfRadius, 0, 3)), shadows.normalOffset, 0.0f);
    frame.ao = glm::vec4(float(std::clamp(settings.ao.samples, 0, 16)), settings.ao.distance,
                         settings.ao.strength, settings.fxaa ? 1.0f : 0.0f);
    frame.fog = glm::vec4(0.0f);
    frame.orthoRight = glm::vec4(camera.orthoRight, 0.0f);
    frame.orthoUp = glm::vec4(camera.orthoUp, camera.orthographic ? 1.0f : 0.0f);
    return frame;
}

void packEnvironment(const Environment& environment, int imageLevels, GpuFrame& frame) {
    SkyType sky = environment.sky;
    if (sky == SkyType::Image && imageLevels <= 0) sky = SkyType::Constant; // image not loaded
    frame.sky =
        glm::vec4(float(int(sky)), environment.intensity, float(std::max(imageLevels - 1, 0)),
                  glm::radians(environment.rotationDegrees));
    frame.skyZenith =
        glm::vec4(sky == SkyType::Gradient ? environment.zenith : environment.color, 0.0f);
    frame.skyHorizon = glm::vec4(environment.horizon, 0.0f);
    frame.skyGround = glm::vec4(environment.ground, 0.0f);
    frame.fog = glm::vec4(environment.fogColor, environment.fogDensity);
}

} // namespace rmsc
