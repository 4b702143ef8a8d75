// The SDF tree as a scene file describes it: groups combining children with an operation,
// shapes (catalogue primitives or profile solids), modifiers and shells. Compiled by
// sdf/compiler.hpp; read and written by scene/scene_json.hpp.
#pragma once

#include "core/transform.hpp"
#include "sdf/primitives.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

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

// A modifier on an SDF node (docs/scene-format.md, "Modifiers"; one catalogue row each,
// sdf/modifiers.hpp). Point modifiers transform the evaluation point in the node's local frame
// before the node is evaluated, in list order; distance modifiers change the node's distance
// afterwards, in list order. Lengths are in the node's local units, angles in degrees.
enum class SdfModifierType {
    Repeat,   // vector = period per axis (0: not repeated), count per axis (0: infinite)
    Mirror,   // axes = which axes are folded to their absolute value
    Polar,    // count copies around `axis`
    Elongate, // vector = half the stretch per axis
    Twist,    // amount = degrees per unit along y, radius = the content's radius around y
    Bend,     // amount = degrees per unit along x (bend in the xy plane), radius = content radius
    Taper,    // amount = change of the x, z scale per unit along y, radius = the content's reach
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
    float amount = 0.0f;     // Twist, Bend: degrees per unit; Displace: amplitude; Taper: scale
                             // change per unit
    float radius = 0.0f;     // Round; Twist, Bend, Taper: radius the content lies within
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

} // namespace rmsc
