// Face culling of mesh primitives (see face_culling.hpp).
#include "face_culling.hpp"

namespace rmsc {

bool drawsBothFaces(const GpuScene& scene, const GpuMeshInstance& instance,
                    const GpuMeshPrimitive& primitive) {
    if (instance.materialOverride >= 0) return true;
    if (primitive.material < 0) return false; // the glTF default material
    return scene.meshMaterials[std::size_t(instance.mesh)][std::size_t(primitive.material)]
        .doubleSided;
}

void setFrontFace(const GpuMeshInstance& instance) {
    glFrontFace(glm::determinant(glm::mat3(instance.model)) < 0.0f ? GL_CW : GL_CCW);
}

void setFaceCulling(bool bothFaces) {
    if (bothFaces) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    }
}

} // namespace rmsc
