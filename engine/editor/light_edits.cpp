// Lights in the editor (see light_edits.hpp).
#include "editor/light_edits.hpp"

#include "scene/light_spec.hpp"

#include <cmath>
#include <limits>

namespace rmsc::editor {
namespace {

// The shortest rotation that turns unit vector `from` into unit vector `to`.
glm::quat rotationBetween(glm::vec3 from, glm::vec3 to) {
    const float cosine = glm::dot(from, to);
    if (cosine < -0.9999f) {
        // Opposite: half a turn about any axis at right angles to `from`.
        glm::vec3 axis = glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), from);
        if (glm::dot(axis, axis) < 1e-6f) axis = glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), from);
        return glm::angleAxis(glm::pi<float>(), glm::normalize(axis));
    }
    const glm::vec3 axis = glm::cross(from, to);
    // (1 + cos, sin * axis) normalized is the rotation by the angle between them.
    return glm::normalize(glm::quat(1.0f + cosine, axis.x, axis.y, axis.z));
}

} // namespace

Light makeLight(LightType type, glm::vec3 position, int number) {
    Light light;
    light.type = type;
    light.name = std::string(lightTypeName(type)) + " light " + std::to_string(number);
    light.position = position;
    if (type == LightType::Spot) light.direction = kLightRestDirection;
    return light;
}

bool gestureChangesLight(LightType type, GestureKind kind) {
    switch (kind) {
    case GestureKind::Move:
        return hasPosition(type);
    case GestureKind::Rotate:
        return hasDirection(type);
    case GestureKind::Scale:
        break;
    }
    return false;
}

Transform lightTransform(const Light& light) {
    Transform t;
    t.position = light.position;
    const float length = glm::length(light.direction);
    if (hasDirection(light.type) && length > 0.0f)
        t.rotation = rotationBetween(kLightRestDirection, light.direction / length);
    return t;
}

void setLightTransform(Light& light, const Transform& transform) {
    if (hasPosition(light.type)) light.position = transform.position;
    if (hasDirection(light.type))
        light.direction = glm::normalize(transform.rotation * kLightRestDirection);
}

int pickLight(const Scene& scene, const GestureView& view, glm::vec2 mouse, float radiusPixels) {
    int best = -1;
    float bestDistance = radiusPixels;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const glm::vec4 clip = view.viewProjection * glm::vec4(scene.lights[i].position, 1.0f);
        if (clip.w <= 0.0f) continue; // behind the camera
        const float distance = glm::length(worldToScreen(view, scene.lights[i].position) - mouse);
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = int(i);
        }
    }
    return best;
}

std::string lightLabel(const Light& light, int index) {
    if (!light.name.empty()) return light.name;
    return std::string(lightTypeName(light.type)) + " light " + std::to_string(index + 1);
}

} // namespace rmsc::editor
