// The in-memory scene: everything a scene file describes (camera, render settings, lights,
// materials, glTF mesh instances and the SDF tree), independent of GL. Loaded by
// scene_json.hpp, compiled for the GPU by sdf/compiler.hpp, drawn by render/renderer.hpp.
#pragma once

#include "sdf/primitives.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

// Position, rotation and scale; the matrix applies scale, then rotation, then translation.
struct Transform {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // (w, x, y, z)
    glm::vec3 scale{1.0f};

    glm::mat4 matrix() const;
};

// A pinhole camera looking from `position` at `target`.
struct Camera {
    glm::vec3 position{0.0f, 1.5f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f; // vertical field of view
    float nearPlane = 0.05f;
    float farPlane = 200.0f;
};

// Ray-marching and shading settings of a scene.
struct RenderSettings {
    int maxSteps = 256;            // march steps per ray
    float maxDistance = 100.0f;    // rays stop after this distance (world units)
    float surfaceEpsilon = 0.001f; // a ray hits when the distance falls below this (scaled by t)
    glm::vec3 background{0.02f, 0.025f, 0.03f}; // linear RGB where nothing is hit
    glm::vec3 ambient{0.03f};                   // constant ambient light, linear RGB
    float exposure = 1.0f;                      // multiplies HDR colour before tone mapping
};

enum class LightType { Directional };

struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 direction{-0.4f, -1.0f, -0.3f}; // direction the light travels (normalized on load)
    glm::vec3 color{1.0f};                    // linear RGB
    float intensity = 3.0f;                   // illuminance (lux-like units, glTF style)
};

// glTF-style metallic-roughness material.
struct Material {
    std::string name;
    glm::vec3 baseColor{0.8f}; // linear RGB
    float metallic = 0.0f;
    float roughness = 0.5f;
    glm::vec3 emissive{0.0f}; // linear RGB, added to the shaded colour
};

// One placement of a glTF file in the scene. Several instances may name the same file.
struct MeshInstance {
    std::string name;
    std::string file;           // as written in the scene file
    std::filesystem::path path; // resolved against the scene file's folder
    Transform transform;
    int materialOverride = -1;  // index into Scene::materials, or -1 for the glTF's own
    std::string pointer;        // JSON pointer of this instance, for messages
};

enum class SdfOp {
    Union,
    Subtraction,  // first child minus all later children
    Intersection,
    SmoothUnion,  // polynomial smooth minimum, `smoothness` in world units
    SmoothSubtraction,
    SmoothIntersection,
};

// A node of the SDF tree: a group combining its children with an operation, or a shape.
struct SdfNode {
    std::string name;
    std::string pointer; // JSON pointer of this node in the scene file, for messages
    Transform transform; // relative to the parent group
    int material = -1;   // index into Scene::materials; -1 inherits the parent's (or default)

    bool isGroup = false;
    // group
    SdfOp op = SdfOp::Union;
    float smoothness = 0.0f; // k of the smooth operations, world units
    std::vector<SdfNode> children;
    // shape
    PrimitiveId primitive = PrimitiveId::Sphere;
    PrimitiveParams params{}; // laid out as the catalogue row says
};

struct Scene {
    int version = 1;
    std::filesystem::path file; // the scene file, "" for scenes built in code
    Camera camera;
    RenderSettings render;
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<MeshInstance> meshes;
    std::optional<SdfNode> sdf;
};

// Object ids shown by the `id` AOV and used for picking: 0 is the background, mesh instance i
// is kMeshIdBase + i, the SDF node with pre-order index n (root = 0) is kSdfIdBase + n.
constexpr unsigned kMeshIdBase = 1;
constexpr unsigned kSdfIdBase = 0x10000;

} // namespace rmsc
