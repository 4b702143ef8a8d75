// Animation time for a prepared scene: re-poses every mesh asset that shows a glTF animation
// (the scene file's "animation" of its mesh instance, or --animation for a glTF file opened by
// itself) at a new time.
#pragma once

#include "core/diagnostics.hpp"
#include "prepare/prepared_scene.hpp"

namespace rmsc {

// Poses every asset whose pose names an animation at `time` seconds (its pose's time is set to
// it). Returns false, with the problem in `diagnostics`, when one cannot be posed.
bool setSceneAnimationTime(PreparedScene& prepared, double time, Diagnostics& diagnostics);

// The longest of the animations the scene's assets show (0 when none does).
double sceneAnimationDuration(const PreparedScene& prepared);

} // namespace rmsc
