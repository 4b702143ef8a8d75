// Warnings for the glTF features rmsc does not draw (see gltf_unsupported.hpp).
#include "gltf_unsupported.hpp"

#include <string>

namespace rmsc::gltf {

void warnUnsupportedFeatures(const tinygltf::Model& model, Reporter& report) {
    // Skin attributes without a skin to bind them: at the first primitive that has them.
    if (!model.skins.empty()) return;
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            if (!primitive.attributes.count("JOINTS_0")) continue;
            report.warning("/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p) +
                               "/attributes/JOINTS_0",
                           "the file has no skins, so the mesh is drawn unskinned");
            return;
        }
}

} // namespace rmsc::gltf
