// C++ distance functions of the primitive catalogue rows added beyond the basic shapes of
// primitives.cpp: the rest of Inigo Quilez's 3D distance functions (primitive_formulas.cpp) and
// the fractals (fractal_formulas.cpp). Each takes the local point and the row's packed
// parameters and mirrors the GLSL function of the same name in shaders/common/sdf_primitives.glsl.
#pragma once

#include <glm/glm.hpp>

namespace rmsc::formulas {

// Quilez, "Distance functions" (https://iquilezles.org/articles/distfunctions/).
float boxFrame(glm::vec3 p, const float* a);
float cappedTorus(glm::vec3 p, const float* a);
float link(glm::vec3 p, const float* a);
float infiniteCylinder(glm::vec3 p, const float* a);
float cone(glm::vec3 p, const float* a);
float infiniteCone(glm::vec3 p, const float* a);
float hexPrism(glm::vec3 p, const float* a);
float triPrism(glm::vec3 p, const float* a);
float capsuleBetween(glm::vec3 p, const float* a);
float cappedCylinderBetween(glm::vec3 p, const float* a);
float roundedCylinder(glm::vec3 p, const float* a);
float cappedCone(glm::vec3 p, const float* a);
float cappedConeBetween(glm::vec3 p, const float* a);
float solidAngle(glm::vec3 p, const float* a);
float cutSphere(glm::vec3 p, const float* a);
float cutHollowSphere(glm::vec3 p, const float* a);
float deathStar(glm::vec3 p, const float* a);
float roundCone(glm::vec3 p, const float* a);
float roundConeBetween(glm::vec3 p, const float* a);
float revolvedVesica(glm::vec3 p, const float* a);
float rhombus(glm::vec3 p, const float* a);
float octahedron(glm::vec3 p, const float* a);
float pyramid(glm::vec3 p, const float* a);
float triangle(glm::vec3 p, const float* a);
float quad(glm::vec3 p, const float* a);

// Fractal distance estimators with a bounding sphere (fractal_formulas.cpp).
float mandelbulb(glm::vec3 p, const float* a);
float mengerSponge(glm::vec3 p, const float* a);
float sierpinskiTetrahedron(glm::vec3 p, const float* a);
float quaternionJulia(glm::vec3 p, const float* a);

} // namespace rmsc::formulas
