// rmsc render's animation and camera options: --time, --animation, --frames A:B with --fps and
// an output pattern, --camera and --scene, read, checked against the opened file and applied to
// the prepared scene frame by frame.
#pragma once

#include "options.hpp"
#include "prepare/prepared_scene.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace rmsc::app {

struct RenderTiming {
    std::optional<double> time;        // --time
    std::string animation;             // --animation ("" = the first, when a time is asked for)
    bool sequence = false;             // --frames given
    int firstFrame = 0, lastFrame = 0; // --frames A:B, inclusive
    double fps = 24.0;                 // --fps
    std::string camera;                // --camera ("" = rmsc's framing camera)
    int scene = -1;                    // --scene
    bool gltfFile = false;             // the input is a .gltf/.glb file

    double frameTime(int frame) const { return frame / fps; }
};

// Reads the options; prints the problem and returns false on a bad value or combination.
bool readRenderTiming(const ParsedArgs& args, const std::string& inputPath, RenderTiming& out);

// Picks the animation and camera in the opened scene and poses it at the first time. Returns
// kExitOk, or kExitBadInput after printing what exists.
int applyRenderTiming(const RenderTiming& timing, PreparedScene& prepared);

// Poses the scene at `time` and, with --camera, moves the scene camera to the glTF camera at
// that time; false after printing why.
bool poseAtTime(const RenderTiming& timing, double time, PreparedScene& prepared);

// The output file of frame `frame`: the pattern's one %d or %0Nd replaced by the number.
std::filesystem::path frameFile(const std::string& pattern, int frame);
// Whether `pattern` holds exactly one %d or %0Nd (N from 1 to 9) and no other %.
bool isFramePattern(const std::string& pattern);

} // namespace rmsc::app
