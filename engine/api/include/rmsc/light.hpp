// rmsc public API: lights given in code. A Light has the keys and valid values of a light of
// the scene format ("lights" in docs/scene-format.md): a host draws a scene's SDF objects with
// lights of its own through Renderer::drawInto, checked as a scene file's lights are.
#pragma once

#include <array>
#include <string>

namespace rmsc::api {

struct Light {
    enum class Type { Directional, Point, Spot };
    Type type = Type::Directional;
    std::string name;                                 // shown in messages only
    std::array<float, 3> direction{-0.4f, -1, -0.3f}; // directional, spot: the way it travels
    std::array<float, 3> position{0, 2, 0};           // point, spot
    std::array<float, 3> color{1, 1, 1};              // linear RGB, components >= 0
    float intensity = 3;       // >= 0: directional lux-like, point and spot candela-like
    float range = 0;           // point, spot: > 0 where the light ends; 0 = unlimited
    float innerAngle = 0;      // spot: degrees, [0, 90], below outerAngle
    float outerAngle = 45;     // spot: degrees, (0, 90]
    bool castShadows = true;   // when the scene's render.shadows are on
    float shadowSoftness = -1; // [0.001, 1]; negative = the scene's render.shadows.softness
};

} // namespace rmsc::api
