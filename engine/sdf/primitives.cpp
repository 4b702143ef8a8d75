// The primitive catalogue rows and their C++ distance functions. Formulas follow Inigo Quilez,
// "Distance functions" (https://iquilezles.org/articles/distfunctions/); the GLSL versions in
// shaders/common/sdf_primitives.glsl must stay identical.
#include "sdf/primitives.hpp"

#include "primitive_formulas.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <sstream>

namespace rmsc {
namespace {

using glm::vec2;
using glm::vec3;

constexpr float kBig = 1.0e4f; // upper bound of lengths in the scene format

// The rows' unit column: Metres, Degrees, Count or None.
using enum Unit;

vec3 v3(const float* p) {
    return vec3(p[0], p[1], p[2]);
}

float sdSphere(vec3 p, const float* a) {
    return glm::length(p) - a[0];
}

float sdBox(vec3 p, const float* a) {
    const vec3 q = glm::abs(p) - v3(a);
    return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

float sdRoundBox(vec3 p, const float* a) {
    const float r = a[3];
    const vec3 q = glm::abs(p) - v3(a) + r;
    return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f) - r;
}

float sdTorus(vec3 p, const float* a) {
    const vec2 q(glm::length(vec2(p.x, p.z)) - a[0], p.y);
    return glm::length(q) - a[1];
}

float sdCappedCylinder(vec3 p, const float* a) {
    const vec2 d = glm::abs(vec2(glm::length(vec2(p.x, p.z)), p.y)) - vec2(a[0], a[1]);
    return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, 0.0f));
}

float sdPlane(vec3 p, const float* a) {
    const vec3 n = v3(a);
    return glm::dot(p, n) / std::max(glm::length(n), 1e-6f) - a[3];
}

// A gyroid sheet: the level set |g| <= ... of Schoen's gyroid approximated by its trigonometric
// equation g(q) = sin qx cos qy + sin qy cos qz + sin qz cos qx, q = p * 2 pi / period (Schoen,
// "Infinite periodic minimal surfaces without self-intersections", NASA TN D-5541, 1970). Not a
// distance: a bound. The x component of grad g is cos qx cos qy - sin qz sin qx, at most
// sqrt(cos^2 qx + sin^2 qx) * sqrt(cos^2 qy + sin^2 qz) by Cauchy-Schwarz, and summing the
// three squared components so gives |grad g|^2 <= 3. So |g(s p)| / (sqrt(3) s) is 1-Lipschitz in
// p, and so is that minus the half thickness: a safe step for sphere tracing.
float sdGyroid(vec3 p, const float* a) {
    const float s = 6.28318531f / a[0];
    const vec3 q = p * s;
    const float g = std::sin(q.x) * std::cos(q.y) + std::sin(q.y) * std::cos(q.z) +
                    std::sin(q.z) * std::cos(q.x);
    return std::abs(g) / (1.73205081f * s) - a[1];
}

float sdCapsule(vec3 p, const float* a) {
    p.y -= std::clamp(p.y, -a[0], a[0]);
    return glm::length(p) - a[1];
}

float sdEllipsoid(vec3 p, const float* a) {
    const vec3 r = v3(a);
    const float k0 = glm::length(p / r);
    const float k1 = glm::length(p / (r * r));
    return k1 > 0.0f ? k0 * (k0 - 1.0f) / k1 : -std::min(r.x, std::min(r.y, r.z));
}

constexpr ParamSpec kSphere[] = {{"radius", 1, {0.5f}, 0.0f, kBig, "radius", Metres}};
constexpr ParamSpec kBox[] = {
    {"half_extents", 3, {0.5f, 0.5f, 0.5f}, 0.0f, kBig, "half the size along x, y, z", Metres}};
constexpr ParamSpec kRoundBox[] = {
    {"half_extents", 3, {0.5f, 0.5f, 0.5f}, 0.0f, kBig, "half the size along x, y, z", Metres},
    {"radius", 1, {0.1f}, 0.0f, kBig, "edge rounding, taken from inside the box", Metres}};
constexpr ParamSpec kTorus[] = {
    {"major_radius", 1, {0.5f}, 0.0f, kBig, "radius of the ring (in the xz plane)", Metres},
    {"minor_radius", 1, {0.15f}, 0.0f, kBig, "radius of the tube", Metres}};
constexpr ParamSpec kCappedCylinder[] = {
    {"radius", 1, {0.5f}, 0.0f, kBig, "radius", Metres},
    {"half_height", 1, {0.5f}, 0.0f, kBig, "half the height along y", Metres}};
constexpr ParamSpec kPlane[] = {
    {"normal", 3, {0.0f, 1.0f, 0.0f}, -1.0f, 1.0f, "normal (normalized on use), solid below", None},
    {"offset",
     1,
     {0.0f},
     -kBig,
     kBig,
     "distance of the plane from the origin along the normal",
     Metres}};
constexpr ParamSpec kCapsule[] = {
    {"half_height", 1, {0.5f}, 0.0f, kBig, "half the length of the axis segment along y", Metres},
    {"radius", 1, {0.25f}, 0.0f, kBig, "radius", Metres}};
constexpr ParamSpec kEllipsoid[] = {
    {"radii", 3, {0.6f, 0.4f, 0.3f}, 1e-4f, kBig, "semi-axes along x, y, z", Metres}};

// Parameters of the rows whose formulas live in primitive_formulas.cpp / fractal_formulas.cpp.
constexpr ParamSpec kBoxFrame[] = {
    {"half_extents",
     3,
     {0.5f, 0.5f, 0.5f},
     0.0f,
     kBig,
     "half the outer size along x, y, z",
     Metres},
    {"thickness", 1, {0.05f}, 0.0f, kBig, "half the thickness of the frame's bars", Metres}};
constexpr ParamSpec kCappedTorus[] = {
    {"angle",
     1,
     {130.0f},
     0.0f,
     180.0f,
     "degrees: the arc spans this angle either side of +y (180 = a full ring)",
     Degrees},
    {"major_radius", 1, {0.4f}, 0.0f, kBig, "radius of the ring (in the xy plane)", Metres},
    {"minor_radius", 1, {0.1f}, 0.0f, kBig, "radius of the tube", Metres}};
constexpr ParamSpec kLink[] = {
    {"half_length",
     1,
     {0.25f},
     0.0f,
     kBig,
     "half the length of the straight sides (along y)",
     Metres},
    {"major_radius", 1, {0.3f}, 0.0f, kBig, "radius of the rounded ends (in the xy plane)", Metres},
    {"minor_radius", 1, {0.08f}, 0.0f, kBig, "radius of the tube", Metres}};
constexpr ParamSpec kInfiniteCylinder[] = {{"radius", 1, {0.5f}, 0.0f, kBig, "radius", Metres}};
constexpr ParamSpec kCone[] = {
    {"angle", 1, {25.0f}, 0.01f, 89.0f, "degrees between the axis and the side", Degrees},
    {"height", 1, {1.0f}, 1e-4f, kBig, "apex at y = height / 2, base at y = -height / 2", Metres}};
constexpr ParamSpec kInfiniteCone[] = {
    {"angle", 1, {25.0f}, 0.01f, 89.0f, "degrees between the axis and the side", Degrees}};
constexpr ParamSpec kHexPrism[] = {
    {"radius", 1, {0.4f}, 0.0f, kBig, "distance from the axis to each side of the hexagon", Metres},
    {"half_length", 1, {0.4f}, 0.0f, kBig, "half the length along z", Metres}};
constexpr ParamSpec kTriPrism[] = {
    {"radius",
     1,
     {0.3f},
     0.0f,
     kBig,
     "distance from the axis to each side of the triangle",
     Metres},
    {"half_length", 1, {0.4f}, 0.0f, kBig, "half the length along z", Metres}};
constexpr ParamSpec kCapsuleBetween[] = {
    {"a", 3, {-0.3f, -0.3f, 0.0f}, -kBig, kBig, "one end of the axis segment", Metres},
    {"b", 3, {0.3f, 0.3f, 0.0f}, -kBig, kBig, "the other end", Metres},
    {"radius", 1, {0.2f}, 0.0f, kBig, "radius", Metres}};
constexpr ParamSpec kCappedCylinderBetween[] = {
    {"a", 3, {0.0f, -0.5f, 0.0f}, -kBig, kBig, "centre of one cap", Metres},
    {"b", 3, {0.0f, 0.5f, 0.0f}, -kBig, kBig, "centre of the other cap", Metres},
    {"radius", 1, {0.4f}, 0.0f, kBig, "radius", Metres}};
constexpr ParamSpec kRoundedCylinder[] = {
    {"radius", 1, {0.4f}, 0.0f, kBig, "outer radius", Metres},
    {"edge_radius",
     1,
     {0.1f},
     0.0f,
     kBig,
     "rounding of the rims (at most the radius and the half height)",
     Metres},
    {"half_height", 1, {0.5f}, 0.0f, kBig, "half the outer height along y", Metres}};
constexpr ParamSpec kCappedCone[] = {
    {"half_height", 1, {0.5f}, 1e-4f, kBig, "half the height along y", Metres},
    {"radius_bottom", 1, {0.5f}, 0.0f, kBig, "radius of the cap at y = -half_height", Metres},
    {"radius_top", 1, {0.2f}, 0.0f, kBig, "radius of the cap at y = +half_height", Metres}};
constexpr ParamSpec kCappedConeBetween[] = {
    {"a", 3, {0.0f, -0.5f, 0.0f}, -kBig, kBig, "centre of one cap", Metres},
    {"b", 3, {0.0f, 0.5f, 0.0f}, -kBig, kBig, "centre of the other cap", Metres},
    {"radius_a", 1, {0.5f}, 0.0f, kBig, "radius of the cap at a", Metres},
    {"radius_b", 1, {0.2f}, 0.0f, kBig, "radius of the cap at b", Metres}};
constexpr ParamSpec kSolidAngle[] = {
    {"angle", 1, {40.0f}, 0.0f, 180.0f, "degrees between the axis (+y) and the side", Degrees},
    {"radius",
     1,
     {0.8f},
     0.0f,
     kBig,
     "radius of the sphere it is cut from (apex at the origin)",
     Metres}};
constexpr ParamSpec kCutSphere[] = {
    {"radius", 1, {0.5f}, 0.0f, kBig, "radius", Metres},
    {"cut_height",
     1,
     {-0.2f},
     -kBig,
     kBig,
     "the part above the plane y = cut_height is kept (clamped to [-radius, radius])",
     Metres}};
constexpr ParamSpec kCutHollowSphere[] = {
    {"radius", 1, {0.5f}, 0.0f, kBig, "radius of the shell's mid-surface", Metres},
    {"cut_height",
     1,
     {0.2f},
     -kBig,
     kBig,
     "the part below the plane y = cut_height is kept (clamped to [-radius, radius])",
     Metres},
    {"thickness", 1, {0.04f}, 0.0f, kBig, "half the thickness of the shell", Metres}};
constexpr ParamSpec kDeathStar[] = {
    {"radius", 1, {0.5f}, 0.0f, kBig, "radius of the sphere", Metres},
    {"cut_radius", 1, {0.35f}, 0.0f, kBig, "radius of the sphere carved out of it", Metres},
    {"cut_distance",
     1,
     {0.5f},
     1e-3f,
     kBig,
     "the carved sphere's centre lies at (cut_distance, 0, 0)",
     Metres}};
constexpr ParamSpec kRoundCone[] = {
    {"radius_bottom", 1, {0.3f}, 0.0f, kBig, "radius of the sphere at y = -height / 2", Metres},
    {"radius_top", 1, {0.15f}, 0.0f, kBig, "radius of the sphere at y = +height / 2", Metres},
    {"height",
     1,
     {0.6f},
     1e-4f,
     kBig,
     "distance between the spheres' centres (at least the difference of the radii)",
     Metres}};
constexpr ParamSpec kRoundConeBetween[] = {
    {"a", 3, {0.0f, -0.3f, 0.0f}, -kBig, kBig, "centre of one sphere", Metres},
    {"b", 3, {0.0f, 0.3f, 0.0f}, -kBig, kBig, "centre of the other sphere", Metres},
    {"radius_a", 1, {0.3f}, 0.0f, kBig, "radius of the sphere at a", Metres},
    {"radius_b", 1, {0.15f}, 0.0f, kBig, "radius of the sphere at b", Metres}};
constexpr ParamSpec kRevolvedVesica[] = {
    {"a", 3, {0.0f, -0.5f, 0.0f}, -kBig, kBig, "one tip", Metres},
    {"b", 3, {0.0f, 0.5f, 0.0f}, -kBig, kBig, "the other tip", Metres},
    {"width",
     1,
     {0.25f},
     1e-4f,
     kBig,
     "largest radius, at the middle (at most |b - a| / 2)",
     Metres}};
constexpr ParamSpec kRhombus[] = {
    {"half_diagonal_x", 1, {0.5f}, 1e-4f, kBig, "half the diagonal along x", Metres},
    {"half_diagonal_z", 1, {0.3f}, 1e-4f, kBig, "half the diagonal along z", Metres},
    {"half_height", 1, {0.05f}, 0.0f, kBig, "half the thickness along y", Metres},
    {"radius", 1, {0.05f}, 0.0f, kBig, "rounding of the sides (added outside)", Metres}};
constexpr ParamSpec kOctahedron[] = {
    {"radius", 1, {0.6f}, 0.0f, kBig, "distance from the centre to each vertex", Metres}};
constexpr ParamSpec kPyramid[] = {
    {"base", 1, {1.0f}, 1e-4f, kBig, "side of the square base", Metres},
    {"height", 1, {1.0f}, 0.0f, kBig, "base at y = -height / 2, apex at y = +height / 2", Metres}};
constexpr ParamSpec kTriangle[] = {
    {"a", 3, {-0.5f, -0.4f, 0.0f}, -kBig, kBig, "first corner", Metres},
    {"b", 3, {0.5f, -0.4f, 0.0f}, -kBig, kBig, "second corner", Metres},
    {"c", 3, {0.0f, 0.5f, 0.0f}, -kBig, kBig, "third corner", Metres},
    {"thickness", 1, {0.02f}, 0.0f, kBig, "half the thickness (0 = a sheet)", Metres}};
constexpr ParamSpec kQuad[] = {
    {"a", 3, {-0.5f, -0.5f, 0.0f}, -kBig, kBig, "first corner", Metres},
    {"b", 3, {0.5f, -0.5f, 0.0f}, -kBig, kBig, "second corner", Metres},
    {"c", 3, {0.5f, 0.5f, 0.0f}, -kBig, kBig, "third corner", Metres},
    {"d", 3, {-0.5f, 0.5f, 0.0f}, -kBig, kBig, "fourth corner (the four in one plane)", Metres}};
constexpr ParamSpec kMandelbulb[] = {
    {"power", 1, {8.0f}, 2.0f, 16.0f, "exponent n of z -> z^n + c", None},
    {"iterations", 1, {8.0f}, 1.0f, 16.0f, "iterations (floored)", Count},
    {"bailout", 1, {2.0f}, 1.5f, 16.0f, "escape radius", None}};
constexpr ParamSpec kMengerSponge[] = {
    {"iterations", 1, {4.0f}, 0.0f, 8.0f, "levels of holes (floored)", Count},
    {"half_size", 1, {0.5f}, 1e-4f, kBig, "half the edge of the cube", Metres}};
constexpr ParamSpec kSierpinskiTetrahedron[] = {
    {"iterations", 1, {6.0f}, 0.0f, 16.0f, "levels of subdivision (floored)", Count},
    {"size", 1, {0.5f}, 1e-4f, kBig, "the corners lie at (+-size, +-size, +-size)", Metres}};
constexpr ParamSpec kQuaternionJulia[] = {
    {"c_r", 1, {-0.45f}, -2.0f, 2.0f, "real part of the constant c", None},
    {"c_i", 1, {-0.45f}, -2.0f, 2.0f, "i part of c", None},
    {"c_j", 1, {0.18f}, -2.0f, 2.0f, "j part of c", None},
    {"c_k", 1, {0.31f}, -2.0f, 2.0f, "k part of c", None},
    {"iterations", 1, {10.0f}, 1.0f, 32.0f, "iterations (floored)", Count}};

constexpr ParamSpec kGyroid[] = {
    {"period", 1, {1.0f}, 1e-3f, kBig, "length of one cell of the lattice along each axis", Metres},
    {"thickness",
     1,
     {0.05f},
     0.0f,
     kBig,
     "half the sheet's thickness where the surface is steepest; more elsewhere (0 = a sheet)",
     Metres}};

constexpr const char* kIq = "Quilez, Distance functions";
constexpr const char* kIqMandelbulb =
    "Quilez, Mandelbulb (https://iquilezles.org/articles/mandelbulb/)";
constexpr const char* kIqMenger =
    "Quilez, Menger fractal (https://iquilezles.org/articles/menger/)";
constexpr const char* kChristensen =
    "Christensen, Distance Estimated 3D Fractals (III): Folding Space";
constexpr const char* kHart =
    "Hart, Sandin, Kauffman, Ray tracing deterministic 3-D fractals (1989)";

const PrimitiveSpec kCatalogue[] = {
    {PrimitiveId::Sphere, "sphere", "sdSphere", true, kSphere, sdSphere, "a sphere at the origin",
     kIq},
    {PrimitiveId::Box, "box", "sdBox", true, kBox, sdBox, "an axis-aligned box", kIq},
    {PrimitiveId::RoundBox, "round_box", "sdRoundBox", true, kRoundBox, sdRoundBox,
     "a box with rounded edges", kIq},
    {PrimitiveId::Torus, "torus", "sdTorus", true, kTorus, sdTorus, "a ring in the xz plane", kIq},
    {PrimitiveId::CappedCylinder, "capped_cylinder", "sdCappedCylinder", true, kCappedCylinder,
     sdCappedCylinder, "a cylinder along y with flat caps", kIq},
    {PrimitiveId::Plane, "plane", "sdPlane", true, kPlane, sdPlane,
     "an infinite plane; the solid is the half-space below it", kIq},
    {PrimitiveId::Capsule, "capsule", "sdVerticalCapsule", true, kCapsule, sdCapsule,
     "a segment along y swept by a sphere", kIq},
    {PrimitiveId::Ellipsoid, "ellipsoid", "sdEllipsoid", false, kEllipsoid, sdEllipsoid,
     "an ellipsoid (a bound, improved by the gradient-length correction)", kIq},
    {PrimitiveId::BoxFrame, "box_frame", "sdBoxFrame", true, kBoxFrame, formulas::boxFrame,
     "the edges of a box as square bars", kIq},
    {PrimitiveId::CappedTorus, "capped_torus", "sdCappedTorus", true, kCappedTorus,
     formulas::cappedTorus, "an arc of a torus in the xy plane, symmetric about +y", kIq},
    {PrimitiveId::Link, "link", "sdLink", true, kLink, formulas::link,
     "a chain link: a torus stretched along y", kIq},
    {PrimitiveId::InfiniteCylinder, "infinite_cylinder", "sdInfiniteCylinder", true,
     kInfiniteCylinder, formulas::infiniteCylinder, "an endless cylinder along y", kIq},
    {PrimitiveId::Cone, "cone", "sdCone", true, kCone, formulas::cone,
     "a cone along y, apex up, with a flat base", kIq},
    {PrimitiveId::InfiniteCone, "infinite_cone", "sdInfiniteCone", true, kInfiniteCone,
     formulas::infiniteCone, "an endless cone, apex at the origin, opening towards -y", kIq},
    {PrimitiveId::HexPrism, "hex_prism", "sdHexPrism", true, kHexPrism, formulas::hexPrism,
     "a hexagonal prism along z", kIq},
    {PrimitiveId::TriPrism, "tri_prism", "sdTriPrism", false, kTriPrism, formulas::triPrism,
     "a triangular prism along z, a corner towards +y (a bound: the largest face distance)", kIq},
    {PrimitiveId::CapsuleBetween, "capsule_between", "sdCapsuleBetween", true, kCapsuleBetween,
     formulas::capsuleBetween, "the segment from a to b swept by a sphere", kIq},
    {PrimitiveId::CappedCylinderBetween, "capped_cylinder_between", "sdCappedCylinderBetween", true,
     kCappedCylinderBetween, formulas::cappedCylinderBetween,
     "a cylinder from a to b with flat caps", kIq},
    {PrimitiveId::RoundedCylinder, "rounded_cylinder", "sdRoundedCylinder", true, kRoundedCylinder,
     formulas::roundedCylinder, "a cylinder along y with rounded rims (outer size given)", kIq},
    {PrimitiveId::CappedCone, "capped_cone", "sdCappedCone", true, kCappedCone,
     formulas::cappedCone, "a cone along y cut by two flat caps", kIq},
    {PrimitiveId::CappedConeBetween, "capped_cone_between", "sdCappedConeBetween", true,
     kCappedConeBetween, formulas::cappedConeBetween, "a capped cone from a to b", kIq},
    {PrimitiveId::SolidAngle, "solid_angle", "sdSolidAngle", true, kSolidAngle,
     formulas::solidAngle, "a cone of a sphere (an ice-cream scoop), apex at the origin, along +y",
     kIq},
    {PrimitiveId::CutSphere, "cut_sphere", "sdCutSphere", true, kCutSphere, formulas::cutSphere,
     "a sphere with its bottom cut off flat", kIq},
    {PrimitiveId::CutHollowSphere, "cut_hollow_sphere", "sdCutHollowSphere", true, kCutHollowSphere,
     formulas::cutHollowSphere, "a spherical shell cut open at the top (a bowl)", kIq},
    {PrimitiveId::DeathStar, "death_star", "sdDeathStar", true, kDeathStar, formulas::deathStar,
     "a sphere with a spherical dent towards +x", kIq},
    {PrimitiveId::RoundCone, "round_cone", "sdRoundCone", true, kRoundCone, formulas::roundCone,
     "two spheres on the y axis and the cone tangent to both", kIq},
    {PrimitiveId::RoundConeBetween, "round_cone_between", "sdRoundConeBetween", true,
     kRoundConeBetween, formulas::roundConeBetween,
     "spheres at a and b and the cone tangent to both", kIq},
    {PrimitiveId::RevolvedVesica, "revolved_vesica", "sdRevolvedVesica", true, kRevolvedVesica,
     formulas::revolvedVesica, "a lens-shaped spindle from a to b (a vesica revolved)", kIq},
    {PrimitiveId::Rhombus, "rhombus", "sdRhombus", true, kRhombus, formulas::rhombus,
     "a flat rhombus in the xz plane with rounded sides", kIq},
    {PrimitiveId::Octahedron, "octahedron", "sdOctahedron", true, kOctahedron, formulas::octahedron,
     "a regular octahedron, vertices on the axes", kIq},
    {PrimitiveId::Pyramid, "pyramid", "sdPyramid", true, kPyramid, formulas::pyramid,
     "a square pyramid along y (Quilez's faces plus the base)", kIq},
    {PrimitiveId::Triangle, "triangle", "sdTriangle", true, kTriangle, formulas::triangle,
     "a triangle a, b, c thickened by `thickness`", kIq},
    {PrimitiveId::Quad, "quad", "sdQuad", true, kQuad, formulas::quad,
     "a planar quadrilateral a, b, c, d of no thickness (unsigned distance)", kIq},
    {PrimitiveId::Mandelbulb, "mandelbulb", "sdMandelbulb", false, kMandelbulb,
     formulas::mandelbulb,
     "the Mandelbulb (triplex power, y up) in a bounding sphere of radius 2^(1/(power-1))",
     kIqMandelbulb, 0.8f},
    {PrimitiveId::MengerSponge, "menger_sponge", "sdMengerSponge", false, kMengerSponge,
     formulas::mengerSponge, "the Menger sponge: a cube with crosses of holes at every level",
     kIqMenger},
    {PrimitiveId::SierpinskiTetrahedron, "sierpinski_tetrahedron", "sdSierpinskiTetrahedron", false,
     kSierpinskiTetrahedron, formulas::sierpinskiTetrahedron,
     "the Sierpinski tetrahedron by folding space", kChristensen, 0.8f},
    {PrimitiveId::QuaternionJulia, "quaternion_julia", "sdQuaternionJulia", false, kQuaternionJulia,
     formulas::quaternionJulia,
     "a quaternion Julia set z -> z^2 + c, the slice with fourth component 0", kHart, 0.8f},
    {PrimitiveId::Gyroid, "gyroid", "sdGyroid", false, kGyroid, sdGyroid,
     "an infinite gyroid lattice (a triply periodic sheet); intersect it with a shape to fill it",
     "Schoen, Infinite periodic minimal surfaces without self-intersections (1970)"},
};
static_assert(std::size(kCatalogue) == std::size_t(PrimitiveId::Count));

} // namespace

std::span<const PrimitiveSpec> primitiveCatalogue() {
    return kCatalogue;
}

const PrimitiveSpec& primitiveSpec(PrimitiveId id) {
    assert(std::size_t(id) < std::size(kCatalogue));
    return kCatalogue[std::size_t(id)];
}

const PrimitiveSpec* findPrimitive(std::string_view name) {
    for (const PrimitiveSpec& spec : kCatalogue)
        if (spec.name == name) return &spec;
    return nullptr;
}

int paramOffset(const PrimitiveSpec& spec, int paramIndex) {
    int offset = 0;
    for (int i = 0; i < paramIndex; ++i)
        offset += spec.params[i].components;
    return offset;
}

PrimitiveParams defaultParams(const PrimitiveSpec& spec) {
    PrimitiveParams params{};
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
        const int offset = paramOffset(spec, int(i));
        for (int c = 0; c < spec.params[i].components; ++c)
            params[offset + c] = spec.params[i].value[c];
    }
    return params;
}

std::string primitiveGlslCall(const PrimitiveSpec& spec, std::string_view point,
                              const std::function<std::string(int)>& floatAt) {
    std::string call = std::string(spec.glslFunction) + "(" + std::string(point);
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
        const int offset = paramOffset(spec, int(i));
        if (spec.params[i].components == 1) {
            call += ", " + floatAt(offset);
        } else {
            call += ", vec3(" + floatAt(offset) + ", " + floatAt(offset + 1) + ", " +
                    floatAt(offset + 2) + ")";
        }
    }
    return call + ")";
}

std::string generateGlslDispatch(const std::function<bool(PrimitiveId)>& include) {
    // Float k of the packed parameters lives in a[k], b[k - 4] or c[k - 8].
    auto component = [](int k) {
        return std::string(1, char('a' + k / 4)) + "[" + std::to_string(k % 4) + "]";
    };
    std::ostringstream out;
    out << "// Generated from the primitive catalogue (engine/sdf/primitives.cpp).\n"
        << "float sdfPrimitive(uint id, vec3 p, vec4 a, vec4 b, vec4 c) {\n    switch (id) {\n";
    for (const PrimitiveSpec& spec : kCatalogue) {
        if (include && !include(spec.id)) continue;
        out << "    case " << std::uint32_t(spec.id) << "u: return "
            << primitiveGlslCall(spec, "p", component) << ";\n";
    }
    out << "    }\n    return 1e10;\n}\n";
    return out.str();
}

} // namespace rmsc
