// Reading rendered images back to the CPU: the display colour and the AOVs (view depth, world
// normal, object id). Rows are returned top row first, as image files store them.
#pragma once

#include "core/image_io.hpp"
#include "render/renderer.hpp"

#include <cstdint>

namespace rmsc {

Pixels<std::uint8_t> readDisplayColor(const FrameTargets& targets); // RGBA8 sRGB
Pixels<float> readViewDepth(const FrameTargets& targets);           // 1 channel, kNoDepth = miss
Pixels<float> readNormals(const FrameTargets& targets);             // 3 channels, world
Pixels<float> readMarchSteps(const FrameTargets& targets);          // 1 channel: steps per pixel
Pixels<float> readConeTiles(const FrameTargets& targets); // 2: start distance, steps per tile
Pixels<std::uint32_t> readObjectIds(const FrameTargets& targets); // 1 channel
Pixels<float> readHdrColor(const FrameTargets& targets);          // 3 channels, linear

} // namespace rmsc
