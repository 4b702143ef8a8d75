// The colours rmsc export writes to glTF: a red and a blue sphere blended by a smooth union,
// exported to a .gltf file and read back from it (accessors decoded here, independently of the
// writer): the base colour a glTF viewer computes, baseColorFactor times COLOR_0, is purple on
// the seam and pure red or blue far from it, and a vertex that two primitives share has the same
// colour in both.
#include "export/mesh_writers.hpp"
#include "export/sdf_export.hpp"
#include "scene/scene_json.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <map>
#include <tuple>

using namespace rmsc;

namespace {

std::string fromBase64(const std::string& text) {
    auto digit = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        return c == '+' ? 62 : c == '/' ? 63 : -1;
    };
    std::string out;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        const int d = digit(c);
        if (d < 0) break; // '=' padding
        bits = (bits << 6) | std::uint32_t(d);
        count += 6;
        if (count >= 8) {
            count -= 8;
            out += char((bits >> count) & 0xff);
        }
    }
    return out;
}

// A .gltf file as rmsc export writes it: one buffer embedded as a data URI.
struct GltfFile {
    nlohmann::json doc;
    std::string buffer;

    template <class T> std::vector<T> read(int accessor) const {
        const nlohmann::json& a = doc["accessors"][std::size_t(accessor)];
        const nlohmann::json& view = doc["bufferViews"][a["bufferView"].get<std::size_t>()];
        const std::size_t offset =
            view.value("byteOffset", std::size_t(0)) + a.value("byteOffset", std::size_t(0));
        std::vector<T> out(a["count"].get<std::size_t>());
        EXPECT_LE(offset + out.size() * sizeof(T), buffer.size());
        if (offset + out.size() * sizeof(T) <= buffer.size())
            std::memcpy(out.data(), buffer.data() + offset, out.size() * sizeof(T));
        return out;
    }
};

GltfFile readGltf(const std::string& text) {
    GltfFile file;
    file.doc = nlohmann::json::parse(text);
    const std::string uri = file.doc["buffers"][0]["uri"];
    const std::string prefix = "data:application/octet-stream;base64,";
    EXPECT_EQ(uri.substr(0, prefix.size()), prefix);
    file.buffer = fromBase64(uri.substr(prefix.size()));
    EXPECT_EQ(file.buffer.size(), file.doc["buffers"][0]["byteLength"].get<std::size_t>());
    return file;
}

struct ShownVertex {
    glm::vec3 position;
    glm::vec3 color; // baseColorFactor times COLOR_0
};

// Every vertex of every primitive with the base colour a glTF viewer shows there.
std::vector<ShownVertex> shownVertices(const GltfFile& file, int& primitivesWithColor) {
    std::vector<ShownVertex> out;
    primitivesWithColor = 0;
    for (const nlohmann::json& primitive : file.doc["meshes"][0]["primitives"]) {
        const nlohmann::json& factor =
            file.doc["materials"][primitive["material"].get<std::size_t>()]["pbrMetallicRoughness"]
                    ["baseColorFactor"];
        const glm::vec3 base(factor[0].get<float>(), factor[1].get<float>(),
                             factor[2].get<float>());
        const nlohmann::json& attributes = primitive["attributes"];
        const std::vector<glm::vec3> positions = file.read<glm::vec3>(attributes["POSITION"]);
        std::vector<glm::vec3> colors(positions.size(), glm::vec3(1.0f));
        if (attributes.contains("COLOR_0")) {
            ++primitivesWithColor;
            EXPECT_EQ(file.doc["accessors"][attributes["COLOR_0"].get<std::size_t>()]["type"],
                      "VEC3");
            colors = file.read<glm::vec3>(attributes["COLOR_0"]);
        }
        EXPECT_EQ(colors.size(), positions.size());
        // Every index names a vertex of this primitive.
        for (std::uint32_t i : file.read<std::uint32_t>(primitive["indices"]))
            EXPECT_LT(i, positions.size());
        for (std::size_t v = 0; v < positions.size() && v < colors.size(); ++v)
            out.push_back({positions[v], base * colors[v]});
    }
    return out;
}

class ExportColours : public rmsc::test::TempFolderTest {};

} // namespace

TEST_F(ExportColours, SmoothBlendIsPurpleOnTheSeamAndPureFarFromIt) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(R"({"version": 1,
        "materials": {"red": {"base_color": [1, 0, 0]}, "blue": {"base_color": [0, 0, 1]}},
        "sdf": {"op": "smooth_union", "smoothness": 0.2, "children": [
          {"shape": "sphere", "radius": 0.3, "position": [-0.2, 0, 0], "material": "red"},
          {"shape": "sphere", "radius": 0.3, "position": [0.2, 0, 0], "material": "blue"}]}})",
                                                  "t.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.format();
    ExportSettings settings;
    settings.resolution = 24;
    const std::optional<SdfExport> exported = exportSdf(*scene, settings, diagnostics);
    ASSERT_TRUE(exported) << diagnostics.format();
    std::string error;
    const std::filesystem::path path = folder_ / "blend.gltf";
    ASSERT_TRUE(writeMeshFile(path, MeshFormat::Gltf,
                              {exported->mesh, exported->materials, exported->name}, nullptr,
                              error))
        << error;
    const GltfFile file = readGltf(read(path));
    ASSERT_EQ(file.doc["materials"].size(), 2u);
    ASSERT_EQ(file.doc["meshes"][0]["primitives"].size(), 2u);
    int primitivesWithColor = 0;
    const std::vector<ShownVertex> vertices = shownVertices(file, primitivesWithColor);
    EXPECT_EQ(primitivesWithColor, 2); // both materials' triangles reach into the blend
    int seam = 0, farRed = 0, farBlue = 0;
    for (const ShownVertex& v : vertices) {
        const glm::vec3 c = v.color;
        EXPECT_LT(c.y, 1e-4f) << "no green anywhere";
        // Everywhere a blend of the two: the weights sum to 1, so no channel is lost.
        EXPECT_NEAR(c.x + c.z, 1.0f, 1e-3f) << v.position.x;
        if (std::abs(v.position.x) < 0.005f) {
            // On the seam both spheres weigh the same: half red, half blue (measured 0.5017 /
            // 0.4983 at x = -0.0006, the colour changing by 2.9 per metre along x there).
            ++seam;
            EXPECT_NEAR(c.x, 0.5f, 0.01f) << v.position.x;
            EXPECT_NEAR(c.z, 0.5f, 0.01f) << v.position.x;
        } else if (v.position.x < -0.35f) {
            ++farRed;
            EXPECT_NEAR(c.x, 1.0f, 1e-3f);
            EXPECT_NEAR(c.z, 0.0f, 1e-3f);
        } else if (v.position.x > 0.35f) {
            ++farBlue;
            EXPECT_NEAR(c.x, 0.0f, 1e-3f);
            EXPECT_NEAR(c.z, 1.0f, 1e-3f);
        }
    }
    EXPECT_GE(seam, 4);    // 8 measured (four points, each in both primitives)
    EXPECT_GT(farRed, 60); // 124 and 127 measured
    EXPECT_GT(farBlue, 60);
    // A position in both primitives (where the materials meet) shows one colour.
    std::map<std::tuple<float, float, float>, glm::vec3> seen;
    int shared = 0;
    for (const ShownVertex& v : vertices) {
        const auto key = std::make_tuple(v.position.x, v.position.y, v.position.z);
        auto [it, added] = seen.try_emplace(key, v.color);
        if (added) continue;
        ++shared;
        EXPECT_LT(glm::length(it->second - v.color), 1e-5f) << v.position.x;
    }
    EXPECT_GT(shared, 15); // 30 measured
}

// A material that smooth operations never blend keeps its colour as the factor, without
// COLOR_0.
TEST_F(ExportColours, UnblendedMaterialKeepsItsFactorAndNoColorAttribute) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(R"({"version": 1,
        "materials": {"green": {"base_color": [0.1, 0.7, 0.2]}},
        "sdf": {"shape": "box", "material": "green"}})",
                                                  "t.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.format();
    ExportSettings settings;
    settings.resolution = 8;
    const std::optional<SdfExport> exported = exportSdf(*scene, settings, diagnostics);
    ASSERT_TRUE(exported) << diagnostics.format();
    const GltfFile file =
        readGltf(gltfBytes({exported->mesh, exported->materials, exported->name}, false));
    int primitivesWithColor = 0;
    const std::vector<ShownVertex> vertices = shownVertices(file, primitivesWithColor);
    EXPECT_EQ(primitivesWithColor, 0);
    ASSERT_FALSE(vertices.empty());
    for (const ShownVertex& v : vertices)
        EXPECT_LT(glm::length(v.color - glm::vec3(0.1f, 0.7f, 0.2f)), 1e-6f);
}
