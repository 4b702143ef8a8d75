// glTF import of valid files: the sample assets, node transforms baked into vertices, computed
// normals, non-indexed and strip/fan primitives, and the scene made for viewing one glTF file.
#include "gltf_builder.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/mesh_asset.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <map>

using namespace rmsc;

namespace {

const std::string kAssets = std::string(RMSC_TEST_SOURCE_DIR) + "/samples/assets/";

MeshAsset loadSample(const std::string& name) {
    Diagnostics diagnostics;
    auto asset = loadGltf(kAssets + name, diskFileSource(), diagnostics);
    EXPECT_TRUE(asset.has_value()) << diagnostics.format();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.format();
    return asset.value_or(MeshAsset{});
}

template <typename T> void append(std::string& bytes, const std::vector<T>& values) {
    const std::size_t start = bytes.size();
    bytes.resize(start + values.size() * sizeof(T));
    std::memcpy(bytes.data() + start, values.data(), values.size() * sizeof(T));
    while (bytes.size() % 4)
        bytes += '\0';
}

// A one-mesh glTF with the given float positions (xyz triples), optional normals and u32
// indices, primitive mode and node list; the mesh is mesh 0.
std::string makeGltf(const std::vector<float>& positions, const std::vector<float>& normals,
                     const std::vector<std::uint32_t>& indices, int mode,
                     const nlohmann::json& nodes, const nlohmann::json& sceneRoots) {
    using nlohmann::json;
    std::string bytes;
    json views = json::array(), accessors = json::array(), attributes = json::object();
    const auto addView = [&](const auto& values, int componentType, const char* type,
                             std::size_t count) {
        const std::size_t offset = bytes.size();
        append(bytes, values);
        views.push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size() - offset}});
        accessors.push_back({{"bufferView", views.size() - 1},
                             {"componentType", componentType},
                             {"type", type},
                             {"count", count}});
        return int(accessors.size() - 1);
    };
    attributes["POSITION"] = addView(positions, 5126, "VEC3", positions.size() / 3);
    if (!normals.empty()) attributes["NORMAL"] = addView(normals, 5126, "VEC3", normals.size() / 3);
    json primitive = {{"attributes", attributes}, {"mode", mode}};
    if (!indices.empty()) primitive["indices"] = addView(indices, 5125, "SCALAR", indices.size());
    json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", sceneRoots}}}},
        {"scene", 0},
        {"nodes", nodes},
        {"meshes", {{{"primitives", {primitive}}}}},
        {"accessors", accessors},
        {"bufferViews", views},
        {"buffers",
         {{{"byteLength", bytes.size()},
           {"uri", "data:application/octet-stream;base64," + test::base64Encode(bytes)}}}}};
    return gltf.dump();
}

FileSource memoryFiles(std::map<std::string, std::string> files) {
    return {[files = std::move(files)](const std::filesystem::path& path,
                                       std::string& error) -> std::optional<std::string> {
        const auto it = files.find(path.generic_string());
        if (it != files.end()) return it->second;
        error = "no such file";
        return std::nullopt;
    }};
}

std::optional<MeshAsset> loadText(const std::string& text, Diagnostics& diagnostics) {
    return loadGltf("mem/test.gltf", memoryFiles({{"mem/test.gltf", text}}), diagnostics);
}

glm::vec3 triangleNormal(const MeshPrimitive& p, std::size_t t) {
    const glm::vec3 a = p.vertices[p.indices[t]].position;
    const glm::vec3 b = p.vertices[p.indices[t + 1]].position;
    const glm::vec3 c = p.vertices[p.indices[t + 2]].position;
    return glm::cross(b - a, c - a);
}

void expectUnitNormals(const MeshAsset& asset) {
    for (const MeshPrimitive& p : asset.primitives)
        for (const MeshVertex& v : p.vertices)
            ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
}

// Every triangle's winding agrees with its vertices' normals.
void expectWindingMatchesNormals(const MeshAsset& asset) {
    for (const MeshPrimitive& p : asset.primitives)
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const glm::vec3 n = triangleNormal(p, t);
            for (int k = 0; k < 3; ++k)
                ASSERT_GT(glm::dot(n, p.vertices[p.indices[t + std::size_t(k)]].normal), 0.0f)
                    << "triangle " << t / 3;
        }
}

void expectVec3Near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

} // namespace

TEST(GltfImport, PlaneIsATwoByTwoQuadFacingUp) {
    const MeshAsset asset = loadSample("plane.gltf");
    ASSERT_EQ(asset.primitives.size(), 1u);
    const MeshPrimitive& p = asset.primitives[0];
    EXPECT_EQ(p.vertices.size(), 4u);
    EXPECT_EQ(p.indices.size(), 6u);
    expectVec3Near(asset.boundsMin, {-1, 0, -1});
    expectVec3Near(asset.boundsMax, {1, 0, 1});
    for (const MeshVertex& v : p.vertices) {
        expectVec3Near(v.normal, {0, 1, 0});
        EXPECT_TRUE(v.uv.x == 0.0f || v.uv.x == 1.0f);
    }
    expectWindingMatchesNormals(asset);
    ASSERT_EQ(asset.materials.size(), 1u);
    EXPECT_EQ(p.material, 0);
    EXPECT_FLOAT_EQ(asset.materials[0].baseColorFactor.x, 0.8f);
    EXPECT_FLOAT_EQ(asset.materials[0].metallicFactor, 0.0f);
    EXPECT_FLOAT_EQ(asset.materials[0].roughnessFactor, 0.5f);
    EXPECT_EQ(asset.materials[0].baseColorTexture.image, -1);
}

TEST(GltfImport, CubeHas24VerticesWithFlatOutwardNormals) {
    const MeshAsset asset = loadSample("cube.gltf");
    ASSERT_EQ(asset.primitives.size(), 1u);
    const MeshPrimitive& p = asset.primitives[0];
    EXPECT_EQ(p.vertices.size(), 24u);
    EXPECT_EQ(p.indices.size(), 36u);
    expectVec3Near(asset.boundsMin, glm::vec3(-0.5f));
    expectVec3Near(asset.boundsMax, glm::vec3(0.5f));
    expectUnitNormals(asset);
    for (const MeshVertex& v : p.vertices)
        EXPECT_NEAR(glm::dot(v.normal, v.position), 0.5f, 1e-5f); // normal is the face's axis
    expectWindingMatchesNormals(asset);
    expectVec3Near(glm::vec3(asset.materials.at(0).baseColorFactor), {0.8f, 0.2f, 0.2f});
}

TEST(GltfImport, SphereHasSmoothRadialNormals) {
    const MeshAsset asset = loadSample("sphere.gltf");
    ASSERT_EQ(asset.primitives.size(), 1u);
    const MeshPrimitive& p = asset.primitives[0];
    EXPECT_EQ(p.vertices.size(), 65u * 33u);
    EXPECT_EQ(p.indices.size(), 64u * 62u * 3u);
    expectVec3Near(asset.boundsMin, glm::vec3(-0.5f), 1e-4f);
    expectVec3Near(asset.boundsMax, glm::vec3(0.5f), 1e-4f);
    expectUnitNormals(asset);
    for (const MeshVertex& v : p.vertices) {
        EXPECT_NEAR(glm::length(v.position), 0.5f, 1e-5f);
        expectVec3Near(v.normal, v.position * 2.0f, 1e-4f);
    }
    expectWindingMatchesNormals(asset);
    expectVec3Near(glm::vec3(asset.materials.at(0).baseColorFactor), {0.2f, 0.4f, 0.8f});
}

TEST(GltfImport, CheckerPlaneTextureIsDecodedToRgba) {
    const MeshAsset asset = loadSample("checker_plane.gltf");
    ASSERT_EQ(asset.images.size(), 1u);
    const Image& image = asset.images[0];
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 64);
    ASSERT_EQ(image.rgba.size(), 64u * 64u * 4u);
    const auto pixel = [&](int x, int y) { return &image.rgba[std::size_t(y * 64 + x) * 4]; };
    EXPECT_EQ(pixel(0, 0)[0], 230); // light square
    EXPECT_EQ(pixel(8, 0)[0], 40);  // dark square
    EXPECT_EQ(pixel(8, 8)[1], 230); // light again
    EXPECT_EQ(pixel(63, 0)[2], 40); // 7th square along x is dark
    EXPECT_EQ(pixel(5, 9)[3], 255); // opaque alpha added to RGB
    ASSERT_EQ(asset.materials.size(), 1u);
    EXPECT_EQ(asset.materials[0].baseColorTexture.image, 0);
}

TEST(GltfImport, GlbAndExternalBufferMatchTheGltfCube) {
    const MeshAsset gltf = loadSample("cube.gltf");
    for (const char* name : {"cube.glb", "cube_external.gltf"}) {
        SCOPED_TRACE(name);
        const MeshAsset other = loadSample(name);
        ASSERT_EQ(other.primitives.size(), 1u);
        const MeshPrimitive& a = gltf.primitives.at(0);
        const MeshPrimitive& b = other.primitives[0];
        EXPECT_EQ(a.indices, b.indices);
        ASSERT_EQ(a.vertices.size(), b.vertices.size());
        for (std::size_t i = 0; i < a.vertices.size(); ++i) {
            EXPECT_EQ(a.vertices[i].position, b.vertices[i].position);
            EXPECT_EQ(a.vertices[i].normal, b.vertices[i].normal);
            EXPECT_EQ(a.vertices[i].uv, b.vertices[i].uv);
        }
        // Each sample has its own material colour.
        EXPECT_NE(gltf.materials.at(0).baseColorFactor, other.materials.at(0).baseColorFactor);
    }
}

TEST(GltfImport, LoadsThroughTheEmbeddedFileSource) {
    Diagnostics diagnostics;
    const auto asset =
        loadGltf("samples/assets/cube_external.gltf", embeddedFileSource(), diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    EXPECT_EQ(asset->primitives.at(0).vertices.size(), 24u);
}

TEST(GltfImport, BakesParentTranslationAndChildScale) {
    // Triangle (1,0,0) (0,1,0) (0,0,1); parent translates by (10,0,0), child scales by 2.
    const nlohmann::json nodes = {{{"translation", {10, 0, 0}}, {"children", {1}}},
                                  {{"scale", {2, 2, 2}}, {"mesh", 0}}};
    Diagnostics diagnostics;
    const auto asset = loadText(
        makeGltf({1, 0, 0, 0, 1, 0, 0, 0, 1}, {}, {}, 4, nodes, nlohmann::json{0}), diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    const MeshPrimitive& p = asset->primitives.at(0);
    ASSERT_EQ(p.vertices.size(), 3u);
    expectVec3Near(p.vertices[0].position, {12, 0, 0});
    expectVec3Near(p.vertices[1].position, {10, 2, 0});
    expectVec3Near(p.vertices[2].position, {10, 0, 2});
    expectVec3Near(asset->boundsMin, {10, 0, 0});
    expectVec3Near(asset->boundsMax, {12, 2, 2});
}

TEST(GltfImport, MatrixRotationAndMirroringAreBaked) {
    // Node 0: column-major matrix rotating 90 degrees about z then translating by (0,0,5).
    // Node 1: scale -1 in x (mirror), which must flip the winding.
    const nlohmann::json nodes = {
        {{"matrix", {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}, {"mesh", 0}},
        {{"scale", {-1, 1, 1}}, {"mesh", 0}}};
    const std::vector<float> quad = {0, 0, 0, 1, 0, 0, 1, 1, 0};
    const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    Diagnostics diagnostics;
    const auto asset =
        loadText(makeGltf(quad, normals, {}, 4, nodes, nlohmann::json{0, 1}), diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    ASSERT_EQ(asset->primitives.size(), 2u);
    const MeshPrimitive& rotated = asset->primitives[0];
    expectVec3Near(rotated.vertices[1].position, {0, 1, 5});
    expectVec3Near(rotated.vertices[2].position, {-1, 1, 5});
    EXPECT_EQ(rotated.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    const MeshPrimitive& mirrored = asset->primitives[1];
    expectVec3Near(mirrored.vertices[1].position, {-1, 0, 0});
    EXPECT_EQ(mirrored.indices, (std::vector<std::uint32_t>{0, 2, 1}));
    expectVec3Near(mirrored.vertices[0].normal, {0, 0, 1});
    expectWindingMatchesNormals(*asset);
}

TEST(GltfImport, NonUniformScaleUsesInverseTransposeForNormals) {
    // A plane tilted 45 degrees (normal (0,1,-1)/sqrt2), scaled by 2 in y: the normal becomes
    // proportional to (0, 1/2, -1).
    const nlohmann::json nodes = {{{"scale", {1, 2, 1}}, {"mesh", 0}}};
    const float s = 1.0f / std::sqrt(2.0f);
    Diagnostics diagnostics;
    const auto asset =
        loadText(makeGltf({0, 0, 0, 1, 0, 0, 0, 1, 1}, {0, s, -s, 0, s, -s, 0, s, -s}, {}, 4, nodes,
                          nlohmann::json{0}),
                 diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    expectVec3Near(asset->primitives.at(0).vertices[0].normal,
                   glm::normalize(glm::vec3(0, 0.5f, -1)));
}

TEST(GltfImport, MissingNormalsPointOutwardOnATetrahedron) {
    // Shared vertices: smooth normals; each must point away from the centroid.
    const std::vector<float> positions = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
    const std::vector<std::uint32_t> indices = {0, 1, 3, 0, 2, 1, 0, 3, 2, 1, 2, 3};
    Diagnostics diagnostics;
    const auto asset = loadText(
        makeGltf(positions, {}, indices, 4, nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}),
        diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    const MeshPrimitive& p = asset->primitives.at(0);
    ASSERT_EQ(p.vertices.size(), 4u);
    for (const MeshVertex& v : p.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
        // For a regular tetrahedron centred at the origin the smooth normal is the vertex
        // direction.
        expectVec3Near(v.normal, glm::normalize(v.position), 1e-5f);
    }
}

TEST(GltfImport, MissingNormalsAreFlatWithoutSharedVertices) {
    // The sample cube without its NORMAL attribute: 24 unshared vertices give face normals.
    std::string text;
    {
        std::string error;
        text = diskFileSource().read(kAssets + "cube.gltf", error).value_or("");
    }
    nlohmann::json gltf = nlohmann::json::parse(text);
    gltf["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    Diagnostics diagnostics;
    const auto asset = loadText(gltf.dump(), diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    for (const MeshVertex& v : asset->primitives.at(0).vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v.normal, v.position), 0.5f, 1e-5f); // the face's outward axis
    }
}

TEST(GltfImport, NonIndexedPrimitiveGetsSequentialIndices) {
    Diagnostics diagnostics;
    const auto asset = loadText(makeGltf({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1}, {},
                                         {}, 4, nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}),
                                diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    EXPECT_EQ(asset->primitives.at(0).indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    // No normals in the file, nothing shared: each triangle's normal is its face normal.
    expectVec3Near(asset->primitives[0].vertices[0].normal, {0, 0, 1});
}

TEST(GltfImport, StripAndFanBecomeTriangleLists) {
    // Four vertices of a square in the xy plane, facing +z. Strip triangle i is
    // (v_i, v_{i+1+i%2}, v_{i+2-i%2}) as the glTF specification defines it.
    const std::vector<float> strip = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    Diagnostics diagnostics;
    auto asset = loadText(
        makeGltf(strip, {}, {}, 5, nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}), diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    EXPECT_EQ(asset->primitives.at(0).indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
    for (std::size_t t = 0; t < 6; t += 3)
        EXPECT_GT(triangleNormal(asset->primitives[0], t).z, 0.0f) << "strip keeps winding";

    const std::vector<float> fan = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0, 0};
    asset = loadText(
        makeGltf(fan, {}, {0, 1, 2, 3, 4}, 6, nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}),
        diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    EXPECT_EQ(asset->primitives.at(0).indices,
              (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
    for (std::size_t t = 0; t < 9; t += 3)
        EXPECT_GT(triangleNormal(asset->primitives[0], t).z, 0.0f) << "fan keeps winding";
}

TEST(GltfImport, PointsAndLinesKeepTheirTopology) {
    // glTF 2.0 section 3.7.2.1: LINES pairs, LINE_STRIP joins each vertex to the next,
    // LINE_LOOP also the last to the first, POINTS one index a point; a mirroring node does not
    // reorder them (only triangles have a winding).
    const std::vector<float> square = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const nlohmann::json mirrored = {{{"mesh", 0}, {"scale", {-1, 1, 1}}}};
    struct Case {
        int mode;
        PrimitiveMode expected;
        std::vector<std::uint32_t> indices;
    };
    const Case cases[] = {{0, PrimitiveMode::Points, {0, 1, 2, 3}},
                          {1, PrimitiveMode::Lines, {0, 1, 2, 3}},
                          {2, PrimitiveMode::Lines, {0, 1, 1, 2, 2, 3, 3, 0}},
                          {3, PrimitiveMode::Lines, {0, 1, 1, 2, 2, 3}}};
    for (const Case& c : cases) {
        Diagnostics diagnostics;
        const auto asset =
            loadText(makeGltf(square, {}, {}, c.mode, mirrored, nlohmann::json{0}), diagnostics);
        ASSERT_TRUE(asset) << diagnostics.format();
        EXPECT_TRUE(diagnostics.items.empty()) << "mode " << c.mode << ": " << diagnostics.format();
        ASSERT_EQ(asset->primitives.size(), 1u) << "mode " << c.mode;
        const MeshPrimitive& p = asset->primitives[0];
        EXPECT_EQ(p.mode, c.expected) << "mode " << c.mode;
        EXPECT_EQ(p.indices, c.indices) << "mode " << c.mode;
        EXPECT_EQ(p.indices.size() % indicesPerElement(p.mode), 0u);
        expectVec3Near(p.vertices[1].position, {-1, 0, 0}); // the node's transform applies
        for (const MeshVertex& v : p.vertices) // no NORMAL and nothing to compute one from
            expectVec3Near(v.normal, {0, 0, 0});
    }
}

TEST(GltfImport, LinesFromIndicesAndTheirNormals) {
    // Indexed LINE_STRIP over three of four vertices, with the file's normals kept.
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    Diagnostics diagnostics;
    const auto asset = loadText(makeGltf(positions, normals, {3, 0, 1}, 3,
                                         nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}),
                                diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    ASSERT_EQ(asset->primitives.size(), 1u);
    EXPECT_EQ(asset->primitives[0].indices, (std::vector<std::uint32_t>{3, 0, 0, 1}));
    expectVec3Near(asset->primitives[0].vertices[2].normal, {0, 0, 1});
}

TEST(GltfImport, LinesWithAnOddIndexCountAreRefused) {
    Diagnostics diagnostics;
    const auto asset = loadText(makeGltf({0, 0, 0, 1, 0, 0, 1, 1, 0}, {}, {}, 1,
                                         nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}),
                                diagnostics);
    EXPECT_FALSE(asset);
    EXPECT_NE(diagnostics.format().find("/meshes/0/primitives/0: 3 indices (or vertices) do not "
                                        "form whole lines, expected a multiple of 2"),
              std::string::npos)
        << diagnostics.format();
}

TEST(GltfImport, ALoneVertexMakesNoLine) {
    // A LINE_STRIP of one vertex has no segment: skipped with a warning, like a strip of two.
    Diagnostics diagnostics;
    const auto asset =
        loadText(makeGltf({0, 0, 0}, {}, {}, 3, nlohmann::json{{{"mesh", 0}}}, nlohmann::json{0}),
                 diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    EXPECT_TRUE(asset->primitives.empty());
    EXPECT_FALSE(diagnostics.hasErrors());
    EXPECT_NE(diagnostics.format().find("/meshes/0/primitives/0: warning: primitive has no lines"),
              std::string::npos)
        << diagnostics.format();
}

TEST(GltfImport, SceneFromGltfFramesTheBounds) {
    MeshAsset asset = loadSample("sphere.gltf");
    asset.boundsMin = {1, 2, 3}; // move the box to check the camera follows it
    asset.boundsMax = {3, 4, 5};
    const Scene scene = sceneFromGltf(kAssets + "sphere.gltf", asset);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].file, "sphere.gltf");
    EXPECT_EQ(scene.meshes[0].pointer, "/meshes/0");
    EXPECT_EQ(scene.meshes[0].path, std::filesystem::path(kAssets + "sphere.gltf"));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 3.0f);
    EXPECT_NEAR(glm::length(scene.lights[0].direction), 1.0f, 1e-5f);
    EXPECT_LT(scene.lights[0].direction.y, 0.0f);
    // The neutral studio sky: grey (no tint), brighter above than below.
    EXPECT_EQ(scene.environment.sky, SkyType::Gradient);
    EXPECT_EQ(scene.environment.zenith.x, scene.environment.zenith.z);
    EXPECT_GT(scene.environment.zenith.x, scene.environment.ground.x);
    EXPECT_FALSE(scene.sdf.has_value());

    const Camera& camera = scene.camera;
    expectVec3Near(camera.target, {2, 3, 4});
    const glm::vec3 offset = camera.position - camera.target;
    EXPECT_GT(offset.z, 0.0f);
    EXPECT_GT(offset.y, 0.0f);
    const float radius = std::sqrt(3.0f); // half the box diagonal
    const float distance = glm::length(offset);
    const float halfFov = glm::radians(camera.fovYDegrees) / 2;
    EXPECT_GT(std::asin(radius / distance), halfFov * 0.6f) << "not framed too loosely";
    EXPECT_LT(std::asin(radius / distance), halfFov) << "bounding sphere inside the view";
    EXPECT_LT(camera.nearPlane, distance - radius);
    EXPECT_GT(camera.farPlane, distance + radius);
    EXPECT_GT(camera.nearPlane, 0.0f);
}
