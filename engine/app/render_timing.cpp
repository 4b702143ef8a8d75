// rmsc render's animation and camera options (see render_timing.hpp).
#include "render_timing.hpp"

#include "commands.hpp"
#include "prepare/scene_animation.hpp"
#include "scene/gltf_cameras.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rmsc::app {

namespace {

bool parseInt(const std::string& text, int& out) {
    if (text.empty() || text.size() > 9) return false;
    std::size_t start = text[0] == '-' ? 1 : 0;
    if (start == text.size()) return false;
    for (std::size_t i = start; i < text.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(text[i]))) return false;
    out = std::atoi(text.c_str());
    return true;
}

bool parseSeconds(const std::string& text, double& out) {
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(out);
}

// The %d or %0Nd of a pattern: where it starts and how long it is, or npos.
std::size_t framePlaceholder(const std::string& pattern, std::size_t& length, int& width) {
    std::size_t found = std::string::npos;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (found != std::string::npos) return std::string::npos; // a second %
        std::size_t j = i + 1;
        width = 0;
        if (j < pattern.size() && pattern[j] == '0') {
            ++j;
            if (j >= pattern.size() || pattern[j] < '1' || pattern[j] > '9')
                return std::string::npos;
            width = pattern[j] - '0';
            ++j;
        }
        if (j >= pattern.size() || pattern[j] != 'd') return std::string::npos;
        found = i;
        length = j + 1 - i;
        i = j;
    }
    return found;
}

} // namespace

bool isFramePattern(const std::string& pattern) {
    std::size_t length = 0;
    int width = 0;
    return framePlaceholder(pattern, length, width) != std::string::npos;
}

std::filesystem::path frameFile(const std::string& pattern, int frame) {
    std::size_t length = 0;
    int width = 0;
    const std::size_t at = framePlaceholder(pattern, length, width);
    if (at == std::string::npos) return pattern;
    std::string number = std::to_string(std::abs(frame));
    if (int(number.size()) < width) number.insert(0, std::size_t(width) - number.size(), '0');
    if (frame < 0) number.insert(0, "-");
    return pattern.substr(0, at) + number + pattern.substr(at + length);
}

bool readRenderTiming(const ParsedArgs& args, const std::string& inputPath, RenderTiming& out) {
    std::string extension = std::filesystem::path(inputPath).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    out.gltfFile = extension == ".gltf" || extension == ".glb";
    if (args.has("--time")) {
        double t = 0.0;
        if (!parseSeconds(args.get("--time", ""), t) || t < 0.0) {
            std::fprintf(stderr,
                         "rmsc render: --time: expected seconds (a number >= 0), got '%s'\n",
                         args.get("--time", "").c_str());
            return false;
        }
        out.time = t;
    }
    if (args.has("--frames")) {
        const std::string text = args.get("--frames", "");
        const std::size_t colon = text.find(':');
        if (colon == std::string::npos || !parseInt(text.substr(0, colon), out.firstFrame) ||
            !parseInt(text.substr(colon + 1), out.lastFrame) || out.firstFrame < 0 ||
            out.lastFrame < out.firstFrame) {
            std::fprintf(stderr,
                         "rmsc render: --frames: expected A:B, frame numbers 0 <= A <= B, got "
                         "'%s'\n",
                         text.c_str());
            return false;
        }
        out.sequence = true;
        if (out.time) {
            std::fprintf(stderr, "rmsc render: --time and --frames: give one or the other\n");
            return false;
        }
    }
    if (args.has("--fps")) {
        double fps = 0.0;
        if (!parseSeconds(args.get("--fps", ""), fps) || !(fps > 0.0) || fps > 10000.0) {
            std::fprintf(stderr,
                         "rmsc render: --fps: expected frames a second (a number above "
                         "0, at most 10000), got '%s'\n",
                         args.get("--fps", "").c_str());
            return false;
        }
        if (!out.sequence) {
            std::fprintf(stderr, "rmsc render: --fps is for --frames A:B\n");
            return false;
        }
        out.fps = fps;
    }
    out.animation = args.get("--animation", "");
    out.camera = args.get("--camera", "");
    if (args.has("--scene")) {
        if (!parseInt(args.get("--scene", ""), out.scene) || out.scene < 0) {
            std::fprintf(stderr,
                         "rmsc render: --scene: expected a scene index (0, 1, ...), got "
                         "'%s'\n",
                         args.get("--scene", "").c_str());
            return false;
        }
    }
    for (const char* option : {"--animation", "--camera", "--scene"})
        if (args.has(option) && !out.gltfFile) {
            std::fprintf(stderr,
                         "rmsc render: %s is for a .gltf or .glb file (a scene file names each "
                         "mesh's animation in \"meshes\")\n",
                         option);
            return false;
        }
    return true;
}

int applyRenderTiming(const RenderTiming& timing, PreparedScene& prepared) {
    if (timing.gltfFile && !prepared.assets.empty() && prepared.assets[0].rig) {
        const MeshRig& rig = *prepared.assets[0].rig;
        const std::string file = prepared.assets[0].path.string();
        int animation = -1;
        if (!timing.animation.empty()) {
            std::string why;
            const std::optional<int> found = findAnimation(rig, timing.animation, why);
            if (!found) {
                std::fprintf(stderr, "rmsc render: --animation: %s: %s\n", file.c_str(),
                             why.c_str());
                return kExitBadInput;
            }
            animation = *found;
        } else if (timing.time || timing.sequence) {
            if (rig.animations.empty()) {
                std::fprintf(stderr, "rmsc render: %s: %s: the file has no animations\n",
                             timing.sequence ? "--frames" : "--time", file.c_str());
                return kExitBadInput;
            }
            animation = 0;
        }
        prepared.assetPoses.at(0).animation = animation;
        if (!timing.camera.empty()) {
            std::string why;
            const std::optional<int> camera = findGltfCamera(rig, timing.camera, why);
            if (!camera) {
                std::fprintf(stderr, "rmsc render: --camera: %s: %s\n", file.c_str(), why.c_str());
                return kExitBadInput;
            }
        }
    }
    const double first =
        timing.sequence ? timing.frameTime(timing.firstFrame) : timing.time.value_or(-1.0);
    if (first < 0.0 && timing.camera.empty()) return kExitOk; // nothing to pose
    return poseAtTime(timing, std::max(first, 0.0), prepared) ? kExitOk : kExitBadInput;
}

bool poseAtTime(const RenderTiming& timing, double time, PreparedScene& prepared) {
    Diagnostics diagnostics;
    if ((timing.time || timing.sequence) && !setSceneAnimationTime(prepared, time, diagnostics)) {
        std::fputs(diagnostics.format().c_str(), stderr);
        return false;
    }
    if (timing.camera.empty() || prepared.assets.empty() || !prepared.assets[0].rig) return true;
    const MeshRig& rig = *prepared.assets[0].rig;
    std::string why;
    const std::optional<int> camera = findGltfCamera(rig, timing.camera, why);
    std::optional<Camera> view;
    if (camera) view = gltfCameraAt(rig, *camera, prepared.assetPoses.at(0), why);
    if (!view) {
        std::fprintf(stderr, "rmsc render: --camera: %s: %s\n",
                     prepared.assets[0].path.string().c_str(), why.c_str());
        return false;
    }
    prepared.scene.camera = *view;
    return true;
}

} // namespace rmsc::app
