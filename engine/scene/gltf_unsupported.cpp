// Warnings for the glTF features rmsc does not draw yet (see gltf_unsupported.hpp).
#include "gltf_unsupported.hpp"

#include <string>

namespace rmsc::gltf {

void warnUnsupportedFeatures(const tinygltf::Model& model, Reporter& report) {
    // Morph targets: at the first primitive that has them.
    bool morphs = false, skinned = false;
    for (std::size_t m = 0; m < model.meshes.size() && !(morphs && skinned); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            const std::string pointer =
                "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
            if (!morphs && !primitive.targets.empty()) {
                morphs = true;
                report.warning(pointer + "/targets", "morph targets are not supported yet; the "
                                                     "base mesh is drawn (mesh weights ignored)");
            }
            if (!skinned && primitive.attributes.count("JOINTS_0") && model.skins.empty()) {
                skinned = true;
                report.warning(pointer + "/attributes/JOINTS_0",
                               "skinning is not supported yet; the mesh is drawn unskinned");
            }
        }
    if (!model.skins.empty())
        report.warning("/skins", "skins are not supported yet; meshes are drawn in their bind "
                                 "pose");
    if (!model.animations.empty())
        report.warning("/animations", "animations are not supported yet; the rest pose is drawn");
    if (!model.cameras.empty())
        report.warning("/cameras", "the file's cameras are not used yet; the model is framed "
                                   "by rmsc's own camera");
    if (model.scenes.size() > 1)
        report.warning("/scenes", "the file has " + std::to_string(model.scenes.size()) +
                                      " scenes; only the default one is drawn");
}

} // namespace rmsc::gltf
