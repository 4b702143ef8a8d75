// The single formulas of the CPU evaluator, one per GLSL function of the same name in
// shaders/common/sdf_functions.glsl (operations, modifiers, noise, 2D profiles), taking their
// parameters packed as the program's instructions carry them (sdf/program.hpp). The evaluator
// (sdf/cpu_eval.hpp) runs programs with them; tests compare them with the GLSL one by one. The
// primitives' formulas are the catalogue's (sdf/primitives.hpp, PrimitiveSpec::distance).
#pragma once

#include "sdf/program.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <span>

namespace rmsc {

// Smooth minimum of a and b over a blend region |a - b| < k, and in h how much of a it takes
// (1 where a is far below b, 0 where b is far below a). blend 0: the quadratic polynomial,
// blend 1: a circular arc (SmoothBlend).
float sdfSmoothMin(float a, float b, float k, float blend, float& h);

// a (below) and b (top of the stack) combined with `op`; opParams.x = smoothness k (blend
// width, chamfer or round radius), opParams.y = SmoothBlend. weightA is how much of a's
// material the result carries: 1 or 0 for the hard, chamfer and round operations, the blend
// factor for the smooth ones.
float sdfCombine(SdfOp op, float a, float b, const glm::vec4& opParams, float& weightA);

// The value noise of the Displace modifier, in [-1, 1]; its gradient length is at most
// 3 sqrt(3) (kNoiseGradientBound).
float sdfValueNoise(glm::vec3 p);
constexpr double kNoiseGradientBound = 5.196152422706632;

// Point modifier `kind` applied to p, parameters params[0..2] as SdfOpcode::PointModifier packs
// them (the modifier's catalogue row, sdf/modifiers.hpp).
glm::vec3 sdfPointModifier(SdfPointModifierKind kind, glm::vec3 p, const glm::vec4* params);

// Distance modifier `kind` applied to the distance d at the point p, parameters as
// SdfOpcode::DistanceModifier packs them in params[0].
float sdfDistanceModifier(SdfDistanceModifierKind kind, float d, glm::vec3 p,
                          const glm::vec4& params);

// Signed distance from q to the polygon of `count` points from data[first] (the xy of each).
float sdfPolygonDistance(glm::vec2 q, std::span<const glm::vec4> data, int first, int count);

// The 2D profile `kind` at the local point q, extruded along z or revolved about y, parameters
// as SdfOpcode::Profile packs them; a polygon's points are read from `data`.
float sdfProfile(SdfProfileType kind, glm::vec3 q, const glm::vec4 (&params)[3],
                 std::span<const glm::vec4> data);

} // namespace rmsc
