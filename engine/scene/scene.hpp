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

// One placement of a glTF file in the scene. Several instances may name the same file.
struct MeshInstance {
    std::string name;
    std::string file;           // as written in the scene file
    std::filesystem::path path; // resolved against the scene file's folder
    Transform transform;
    int materialOverride = -1; // index into Scene::materials, or -1 for the glTF's own
    std::string pointer;       // JSON pointer of this instance, for messages
};

enum class SdfOp {
    Union,
    Subtraction, // first child minus all later children
    Intersection,
    SmoothUnion, // smooth minimum (SdfNode::blend), `smoothness` in world units
    SmoothSubtraction,
    SmoothIntersection,
    Xor,          // inside exactly one of the children (folded left to right)
    ChamferUnion, // the seam cut by a 45-degree chamfer of size `smoothness` (hg_sdf)
    ChamferSubtraction,
    ChamferIntersection,
    RoundUnion, // the seam filled by a quarter circle of radius `smoothness` (hg_sdf)
    RoundSubtraction,
    RoundIntersection,
};

// The smooth-minimum curve of the smooth operations (Quilez, "Smooth minimum").
enum class SmoothBlend {
    Polynomial, // quadratic polynomial
    Circular,   // a circular arc
};

// A modifier on an SDF node (docs/scene-format.md, "Modifiers"). Point modifiers (Repeat to
// Bend) transform the evaluation point in the node's local frame before the node is evaluated,
// in list order; distance modifiers (Round, Onion, Displace) change the node's distance
// afterwards, in list order. Lengths are in the node's local units, angles in degrees.
enum class SdfModifierType {
    Repeat,   // vector = period per axis (0: not repeated), count per axis (0: infinite)
    Mirror,   // axes = which axes are folded to their absolute value
    Polar,    // count copies around `axis`
    Elongate, // vector = half the stretch per axis
    Twist,    // amount = degrees per unit along y, radius = the content's radius around y
    Bend,     // amount = degrees per unit along x (bend in the xy plane), radius = content radius
    Round,    // radius subtracted from the distance
    Onion,    // thickness: |d| - thickness
    Displace, // amount = amplitude, frequency of the value noise
};

struct SdfModifier {
    SdfModifierType type = SdfModifierType::Round;
    std::string pointer;     // JSON pointer of the modifier, for messages
    glm::vec3 vector{0.0f};  // Repeat: period; Elongate: half extents
    glm::ivec3 counts{0};    // Repeat: copies per axis, 0 = infinite
    bool neighbours = false; // Repeat: also evaluate the neighbouring cells
    glm::bvec3 axes{false};  // Mirror
    int count = 0;           // Polar: number of copies
    int axis = 1;            // Polar: 0 = x, 1 = y, 2 = z
    float amount = 0.0f;     // Twist, Bend: degrees per unit; Displace: amplitude
    float radius = 0.0f;     // Round; Twist, Bend: radius the content lies within
    float thickness = 0.0f;  // Onion
    float frequency = 1.0f;  // Displace
};

// A 2D profile (in the local xy plane) turned into a solid (docs/scene-format.md, "Profiles").
enum class SdfProfileType { Circle, Rectangle, RoundedRectangle, Polygon };
enum class SdfProfileSolid { Extrusion, Revolution };

struct SdfProfile {
    SdfProfileSolid solid = SdfProfileSolid::Extrusion;
    SdfProfileType type = SdfProfileType::Circle;
    float radius = 0.5f;            // Circle radius; RoundedRectangle corner radius
    glm::vec2 halfSize{0.5f, 0.5f}; // Rectangle, RoundedRectangle
    std::vector<glm::vec2> points;  // Polygon vertices, in order
    float depth = 0.5f;             // Extrusion: full depth along z
    float offset = 0.0f;            // Revolution: distance of the profile's x = 0 from y
};

// What a shell's proxy is: the geometry rasterized so that only its pixels march the shell.
enum class ShellProxy {
    Box,    // the subtree's bounds (sdf/bounds.hpp), or `bound`
    Sphere, // a polyhedron around the sphere that holds the box
    Mesh,   // a glTF file the user names, in the node's frame
};

// Marks a subtree to render in "mesh-shell" mode (docs/scene-format.md, "Shells"): a proxy mesh
// is rasterized and its fragments march only this subtree, in the node's own frame, writing
// gl_FragDepth. It composites with everything else through the depth buffer.
struct SdfShell {
    ShellProxy proxy = ShellProxy::Box;
    std::optional<glm::vec3> bound; // half extents in the node's frame: clamps the content
    std::string meshFile;           // Mesh: as written in the scene file
    std::filesystem::path meshPath; // Mesh: resolved against the scene file's folder
    std::string pointer;            // JSON pointer of the "shell" value, for messages
};

// A node of the SDF tree: a group combining its children with an operation, or a shape.
struct SdfNode {
    std::string name;
    std::string pointer; // JSON pointer of this node in the scene file, for messages
    Transform transform; // relative to the parent group
    int material = -1;   // index into Scene::materials; -1 inherits the parent's (or default)
    std::vector<SdfModifier> modifiers; // applied as SdfModifierType says
    bool cut = false;                   // subtracted from the combination of its non-cut siblings
    std::optional<SdfShell> shell;      // set: drawn through a proxy mesh, not the fullscreen pass

    bool isGroup = false;
    // group
    SdfOp op = SdfOp::Union;
    float smoothness = 0.0f; // k of the smooth operations, chamfer/round radius; world units
    SmoothBlend blend = SmoothBlend::Polynomial; // smooth operations only
    std::vector<SdfNode> children;
    // shape
    PrimitiveId primitive = PrimitiveId::Sphere;
    PrimitiveParams params{};          // laid out as the catalogue row says
    std::optional<SdfProfile> profile; // set: a profile solid, `primitive` is ignored
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

// Object ids shown by the `id` AOV and used for picking: 0 is the background, mesh instance i
// is kMeshIdBase + i, the SDF node with pre-order index n (root = 0) is kSdfIdBase + n.
constexpr unsigned kMeshIdBase = 1;
constexpr unsigned kSdfIdBase = 0x10000;

} // namespace rmsc
