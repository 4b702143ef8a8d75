// Re-posing a prepared scene's animated assets at a time (see scene_animation.hpp).
#include "prepare/scene_animation.hpp"

#include "scene/mesh_pose.hpp"

#include <algorithm>

namespace rmsc {

bool setSceneAnimationTime(PreparedScene& prepared, double time, Diagnostics& diagnostics) {
    for (std::size_t a = 0; a < prepared.assets.size() && a < prepared.assetPoses.size(); ++a) {
        MeshPose& pose = prepared.assetPoses[a];
        if (pose.animation < 0) continue;
        const MeshPose next{pose.animation, time};
        if (!poseMeshAsset(prepared.assets[a], next, diagnostics)) return false;
        pose = next;
    }
    return true;
}

double sceneAnimationDuration(const PreparedScene& prepared) {
    double duration = 0.0;
    for (std::size_t a = 0; a < prepared.assets.size() && a < prepared.assetPoses.size(); ++a) {
        const int animation = prepared.assetPoses[a].animation;
        const MeshAsset& asset = prepared.assets[a];
        if (animation >= 0 && asset.rig && std::size_t(animation) < asset.rig->animations.size())
            duration =
                std::max(duration, double(asset.rig->animations[std::size_t(animation)].duration));
    }
    return duration;
}

} // namespace rmsc
