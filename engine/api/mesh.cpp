// glTF triangles through the engine's importer (the checks and limits of every scene's meshes).
#include "rmsc/mesh.hpp"

#include "scene_impl.hpp"

#include "scene/mesh_asset.hpp"

namespace rmsc::api {

Triangles loadTriangles(const std::string& gltfPath) {
    Diagnostics diagnostics;
    std::optional<MeshAsset> asset = loadGltf(gltfPath, diskFileSource(), diagnostics);
    if (!asset) throw badInput(diagnostics);
    Triangles triangles;
    for (const MeshPrimitive& primitive : asset->primitives) {
        if (primitive.mode != PrimitiveMode::Triangles) continue; // points and lines
        const auto base = std::uint32_t(triangles.positions.size() / 3);
        for (const MeshVertex& vertex : primitive.vertices) {
            triangles.positions.insert(triangles.positions.end(),
                                       {vertex.position.x, vertex.position.y, vertex.position.z});
            triangles.normals.insert(triangles.normals.end(),
                                     {vertex.normal.x, vertex.normal.y, vertex.normal.z});
        }
        for (std::uint32_t index : primitive.indices)
            triangles.indices.push_back(base + index);
    }
    return triangles;
}

} // namespace rmsc::api
