// The primitive catalogue: one row per SDF primitive (name, parameters with defaults and
// valid ranges, GLSL function, C++ function). The scene reader, the validator, the docs,
// `rmsc primitives` and the shader dispatch are all generated from this one table.
#pragma once

#include "core/units.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace rmsc {

enum class PrimitiveId : std::uint32_t {
    Sphere,
    Box,
    RoundBox,
    Torus,
    CappedCylinder,
    Plane,
    Capsule,
    Ellipsoid,
    BoxFrame,
    CappedTorus,
    Link,
    InfiniteCylinder,
    Cone,
    InfiniteCone,
    HexPrism,
    TriPrism,
    CapsuleBetween,
    CappedCylinderBetween,
    RoundedCylinder,
    CappedCone,
    CappedConeBetween,
    SolidAngle,
    CutSphere,
    CutHollowSphere,
    DeathStar,
    RoundCone,
    RoundConeBetween,
    RevolvedVesica,
    Rhombus,
    Octahedron,
    Pyramid,
    Triangle,
    Quad,
    Mandelbulb,
    MengerSponge,
    SierpinskiTetrahedron,
    QuaternionJulia,
    Gyroid,
    Count
};

// A primitive's parameters packed in catalogue order; a vec3 parameter takes three floats.
constexpr int kMaxPrimitiveFloats = 12;
using PrimitiveParams = std::array<float, kMaxPrimitiveFloats>;

struct ParamSpec {
    std::string_view name;        // JSON key, e.g. "radius"
    int components;               // 1 (number) or 3 (vec3)
    std::array<float, 3> value;   // default
    float minValue;               // inclusive; applies to every component
    float maxValue;               // inclusive
    std::string_view description; // one line for docs and --help
    Unit unit;                    // of each component: metres for lengths, degrees for angles
};

struct PrimitiveSpec {
    PrimitiveId id;
    std::string_view name;         // JSON value of "shape", e.g. "round_box"
    std::string_view glslFunction; // function in shaders/common/sdf_primitives.glsl
    bool exact;                    // true: exact distance; false: a lower bound
    std::span<const ParamSpec> params;
    // Distance from local point p, params packed as above. Mirrors the GLSL function.
    float (*distance)(glm::vec3 p, const float* params);
    std::string_view description;
    std::string_view source; // where the formula comes from
    // Distances are multiplied by this while marching: 1 for exact distances and well-behaved
    // bounds, below 1 for bounds that can overestimate near the surface (fractal estimators).
    float stepScale = 1.0f;
};

std::span<const PrimitiveSpec> primitiveCatalogue();
const PrimitiveSpec& primitiveSpec(PrimitiveId id);
const PrimitiveSpec* findPrimitive(std::string_view name); // nullptr if unknown

// Offset of each parameter within PrimitiveParams.
int paramOffset(const PrimitiveSpec& spec, int paramIndex);
// Parameters filled with the catalogue defaults.
PrimitiveParams defaultParams(const PrimitiveSpec& spec);

// The GLSL call of spec's function at `point`, float k of the packed parameters given by
// floatAt(k) (a literal or a buffer read).
std::string primitiveGlslCall(const PrimitiveSpec& spec, std::string_view point,
                              const std::function<std::string(int)>& floatAt);

// GLSL source of `float sdfPrimitive(uint id, vec3 p, vec4 a, vec4 b, vec4 c)`, a switch that
// calls each row's GLSL function with its parameters unpacked from the three vec4s (a = floats
// 0..3, b = floats 4..7, c = floats 8..11): every row, or those `include` accepts.
std::string generateGlslDispatch(const std::function<bool(PrimitiveId)>& include = {});

} // namespace rmsc
