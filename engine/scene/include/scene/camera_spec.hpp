// The valid values of the scene camera's keys (`camera`): the ranges of its lens and the rule
// its position, target and up must follow. The scene reader (scene/scene_json.cpp), the schema
// and the editor's camera fields take them from here, so none of them can disagree.
#pragma once

#include "scene/scene.hpp"
#include "sdf/param_spec.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace rmsc {

// The vertical field of view; near > 0 and far > near.
inline constexpr ParamRange kCameraFovRange = {0.0, 180.0, true, true, Unit::Degrees};
inline constexpr ParamRange kCameraNearRange = {0.0, ParamRange{}.max, true, false, Unit::Metres};
inline constexpr ParamRange kCameraFarRange = {0.0, ParamRange{}.max, true, false, Unit::Metres};
// The height an orthographic camera shows (> 0).
inline constexpr ParamRange kCameraOrthoHeightRange = {0.0, ParamRange{}.max, true, false,
                                                       Unit::Metres};

// The names of the projections in scene files ("projection"): "perspective", "orthographic".
std::string_view cameraProjectionName(CameraProjection projection);
std::optional<CameraProjection> findCameraProjection(std::string_view name);

// What is wrong with a camera's position, target and up: the key to blame and why.
struct CameraProblem {
    std::string_view key; // "target" or "up"
    std::string message;
};

// The target must differ from the position (and lie less than about 1e19 from it, or float
// arithmetic overflows), and up must be finite, non-zero and not parallel to the view.
std::optional<CameraProblem> cameraFrameProblem(const Camera& camera);

} // namespace rmsc
