// Picking skips what the raster pass does not draw (editor/mesh_coverage.hpp): the back faces of
// single-sided materials and the cut-out part of MASK materials (a texture whose alpha is a
// ramp across the square, through its KHR_texture_transform), and keeps double-sided back faces.
#include "editor/mesh_coverage.hpp"
#include "editor/picking.hpp"

#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

// A square of side 2 in the xy plane facing +z (counter-clockwise seen from +z), u = (x + 1) / 2,
// with material 0 = `material`. Image 0: 4x1 texels whose alpha is 0, 85, 170, 255.
PreparedScene squareScene(const MeshMaterial& material) {
    MeshAsset asset;
    MeshPrimitive square;
    for (glm::vec2 corner :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        MeshVertex v{};
        v.position = glm::vec3(corner, 0.0f);
        v.normal = glm::vec3(0, 0, 1);
        v.uv = glm::vec2((corner.x + 1) / 2, (1 - corner.y) / 2);
        square.vertices.push_back(v);
    }
    square.indices = {0, 1, 2, 0, 2, 3};
    square.material = 0;
    asset.primitives.push_back(square);
    asset.materials.push_back(material);
    asset.images.push_back(
        {4, 1, {255, 255, 255, 0, 255, 255, 255, 85, 255, 255, 255, 170, 255, 255, 255, 255}});
    asset.boundsMin = glm::vec3(-1, -1, 0);
    asset.boundsMax = glm::vec3(1, 1, 0);
    PreparedScene prepared;
    prepared.scene.meshes.push_back(MeshInstance{});
    prepared.assets.push_back(asset);
    prepared.instanceAsset.push_back(0);
    return prepared;
}

PickRay ray(float x, float z) {
    PickRay r;
    r.origin = glm::vec3(x, 0.1f, z);
    r.direction = glm::vec3(0, 0, z > 0 ? -1.0f : 1.0f);
    r.tMin = 0.01f;
    r.tMax = 100.0f;
    return r;
}

} // namespace

TEST(PickingCoverage, SingleSidedBackFacesAreNotPicked) {
    MeshMaterial single;
    const PreparedScene prepared = squareScene(single);
    EXPECT_TRUE(pickMesh(prepared, ray(0, 5)));   // front
    EXPECT_FALSE(pickMesh(prepared, ray(0, -5))); // back, culled
    MeshMaterial both;
    both.doubleSided = true;
    EXPECT_TRUE(pickMesh(squareScene(both), ray(0, -5)));
}

TEST(PickingCoverage, MaskCutOutIsNotPicked) {
    MeshMaterial mask;
    mask.alphaMode = AlphaMode::Mask;
    mask.alphaCutoff = 0.5f;
    mask.baseColorTexture.image = 0;
    mask.baseColorTexture.sampler.wrapS = 0x812F; // clamp
    const PreparedScene prepared = squareScene(mask);
    // Texels 0 and 1 (x < 0) have alpha 0 and 1/3, below the cutoff; 2 and 3 are kept.
    EXPECT_FALSE(pickMesh(prepared, ray(-0.75f, 5)));
    EXPECT_FALSE(pickMesh(prepared, ray(-0.25f, 5)));
    EXPECT_TRUE(pickMesh(prepared, ray(0.25f, 5)));
    EXPECT_TRUE(pickMesh(prepared, ray(0.75f, 5)));
    // A texture transform that mirrors u (scale -1, offset 1) moves the cut-out to x > 0.
    mask.baseColorTexture.transform.scale.x = -1.0f;
    mask.baseColorTexture.transform.offset.x = 1.0f;
    const PreparedScene mirrored = squareScene(mask);
    EXPECT_TRUE(pickMesh(mirrored, ray(-0.75f, 5)));
    EXPECT_FALSE(pickMesh(mirrored, ray(0.75f, 5)));
    // BLEND surfaces are seen, so they are picked whatever their alpha.
    mask.alphaMode = AlphaMode::Blend;
    EXPECT_TRUE(pickMesh(squareScene(mask), ray(0.75f, 5)));
}
