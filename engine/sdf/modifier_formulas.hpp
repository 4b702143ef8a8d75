// C++ formulas of the modifier catalogue rows (sdf/modifiers.hpp): each takes the instruction's
// params as the row's `pack` wrote them and mirrors its branch of sdfPointModifier or
// sdfDistanceModifier in shaders/common/sdf_functions.glsl, statement for statement.
#pragma once

#include <glm/glm.hpp>

namespace rmsc::formulas {

// Point modifiers: the point the content is evaluated at.
glm::vec3 repeat(glm::vec3 p, const glm::vec4* a);
glm::vec3 mirror(glm::vec3 p, const glm::vec4* a);
glm::vec3 polar(glm::vec3 p, const glm::vec4* a);
glm::vec3 elongate(glm::vec3 p, const glm::vec4* a);
glm::vec3 twist(glm::vec3 p, const glm::vec4* a);
glm::vec3 bend(glm::vec3 p, const glm::vec4* a);
glm::vec3 taper(glm::vec3 p, const glm::vec4* a);

// Distance modifiers: the distance d changed at the point p.
float round(float d, glm::vec3 p, const glm::vec4* a);
float onion(float d, glm::vec3 p, const glm::vec4* a);
float displace(float d, glm::vec3 p, const glm::vec4* a);

// Value noise (sdfValueNoise in the shader), in [-1, 1]; its gradient length is at most
// 3 sqrt(3) (kNoiseGradientBound).
float valueNoise(glm::vec3 p);
constexpr double kNoiseGradientBound = 5.196152422706632;

} // namespace rmsc::formulas
