// The in-memory scene: everything a scene file describes (camera, render settings, lights,
// materials, glTF mesh instances and the SDF tree), independent of GL. Loaded by
// scene_json.hpp, compiled for the GPU by sdf/compiler.hpp, drawn by render/renderer.hpp.
#pragma once

#include "core/material.hpp"
#include "core/object_ids.hpp"
#include "core/render_settings.hpp"
#include "core/transform.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

// A pinhole camera looking from `position` at `target`.
// How a camera projects: through a point (rays from the eye), or along parallel rays from its
// image plane (orthographic: sizes do not change with distance).
enum class CameraProjection { Perspective, Orthographic };

struct Camera {
    glm::vec3 position{0.0f, 1.5f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f; // vertical field of view (perspective)
    float nearPlane = 0.05f;
    float farPlane = 200.0f;
    CameraProjection projection = CameraProjection::Perspective;
    float orthoHeight = 4.0f; // orthographic: the height of the view in world units

    bool operator==(const Camera&) const = default;
};

// The sky: what rays that hit nothing see and what lights every surface as ambient light.
enum class SkyType { None, Constant, Gradient, Image };

struct Environment {
    SkyType sky = SkyType::None;          // None: render.background behind, render.ambient as light
    glm::vec3 color{0.5f};                // constant sky
    glm::vec3 zenith{0.25f, 0.45f, 0.9f}; // gradient sky: straight up
    glm::vec3 horizon{0.8f, 0.85f, 0.9f}; // at the horizon
    glm::vec3 ground{0.25f, 0.22f, 0.2f}; // below the horizon
    std::string imageFile;                // image sky: as written in the scene file
    std::filesystem::path imagePath;      // resolved against the scene file's folder
    float rotationDegrees = 0.0f;         // image sky: turn about +Y
    float intensity = 1.0f;               // multiplies the sky (background and lighting)
    float fogDensity = 0.0f;              // exponential fog per world unit; 0 = no fog
    glm::vec3 fogColor{0.5f};
};

enum class LightType { Directional, Point, Spot };

// A punctual light, as in glTF KHR_lights_punctual.
struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 direction{-0.4f, -1.0f, -0.3f}; // directional, spot: the way the light travels
    glm::vec3 position{0.0f, 2.0f, 0.0f};     // point, spot
    glm::vec3 color{1.0f};                    // linear RGB
    float intensity = 3.0f;          // directional: lux-like illuminance; point, spot: candela-like
    float range = 0.0f;              // point, spot: distance where the light ends; 0 = unlimited
    float innerAngleDegrees = 0.0f;  // spot: full intensity inside this angle from the axis
    float outerAngleDegrees = 45.0f; // spot: no light outside this angle
    bool castShadows = true;         // when the scene's shadows are enabled
    float shadowSoftness = -1.0f;    // SDF penumbra width factor; < 0 = ShadowSettings::softness
};

// One placement of a glTF file in the scene. Several instances may name the same file.
struct MeshInstance {
    std::string name;
    std::string file;           // as written in the scene file
    std::filesystem::path path; // resolved against the scene file's folder
    Transform transform;
    int materialOverride = -1; // index into Scene::materials, or -1 for the glTF's own
    // The glTF animation it shows, by name or index as written ("" = the file's rest pose),
    // and at which time in seconds.
    std::string animation;
    double time = 0.0;
    int gltfScene = -1;  // "scene": the glTF scene drawn, -1 for the file's default one
    std::string pointer; // JSON pointer of this instance, for messages
};

struct Scene {
    int version = 1;
    std::filesystem::path file; // the scene file, "" for scenes built in code
    Camera camera;
    RenderSettings render;
    Environment environment;
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<MeshInstance> meshes;
    std::optional<SdfNode> sdf;
};

} // namespace rmsc
