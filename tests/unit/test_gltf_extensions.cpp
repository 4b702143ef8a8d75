// glTF extension reporting: an extension marked required that rmsc lacks refuses the file,
// naming it; one used but not supported gets exactly one warning naming it, wherever it is used
// and however often; the supported ones load without a word; the docs list the same table.
#include "gltf_builder.hpp"
#include "scene/gltf_extensions.hpp"
#include "scene/mesh_asset.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>

using namespace rmsc;
using namespace rmsc::test;
using nlohmann::json;

namespace {

// One triangle; `extra` is merged into the document (extension lists, materials...).
std::string triangleGltf(const json& extra) {
    GltfBuilder b;
    const int position =
        b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloatType, "VEC3", 3);
    json gltf = {{"scenes", {{{"nodes", {0}}}}},
                 {"scene", 0},
                 {"nodes", {{{"mesh", 0}}}},
                 {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", position}}}}}}}}}};
    gltf.merge_patch(extra);
    return b.text(gltf);
}

std::optional<MeshAsset> load(const json& extra, Diagnostics& d) {
    return loadGltf("mem/test.gltf", memoryGltf(triangleGltf(extra)), d);
}

// The diagnostics whose message names `word`.
std::vector<Diagnostic> naming(const Diagnostics& d, const std::string& word) {
    std::vector<Diagnostic> out;
    for (const Diagnostic& item : d.items)
        if (item.message.find(word) != std::string::npos) out.push_back(item);
    return out;
}

} // namespace

TEST(GltfExtensions, RequiredButUnsupportedIsRefusedByName) {
    Diagnostics d;
    EXPECT_FALSE(
        load({{"extensionsUsed", {"KHR_texture_transform", "EXT_meshopt_compression"}},
              {"extensionsRequired", {"KHR_texture_transform", "EXT_meshopt_compression"}}},
             d));
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    const std::vector<Diagnostic> refusals = naming(d, "EXT_meshopt_compression");
    ASSERT_EQ(refusals.size(), 1u) << d.format();
    EXPECT_EQ(refusals[0].severity, Severity::Error);
    EXPECT_EQ(refusals[0].location, "/extensionsRequired/1");
    EXPECT_EQ(refusals[0].file, "mem/test.gltf");
}

TEST(GltfExtensions, RequiredAndSupportedLoadsSilently) {
    Diagnostics d;
    std::vector<std::string> all;
    for (const GltfExtensionInfo& e : gltfExtensions())
        all.emplace_back(e.name);
    EXPECT_TRUE(load({{"extensionsUsed", all}, {"extensionsRequired", all}}, d)) << d.format();
    EXPECT_EQ(d.items.size(), 0u) << d.format();
}

TEST(GltfExtensions, UsedButUnsupportedWarnsOnceNamingIt) {
    Diagnostics d;
    // Declared and used twice (a material and a node), plus one used but not declared.
    const json extra = {
        {"extensionsUsed", {"KHR_materials_clearcoat", "KHR_texture_transform"}},
        {"materials",
         {{{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}}}}}},
          {{"extensions", {{"KHR_materials_clearcoat", json::object()}}}}}},
        {"nodes", {{{"mesh", 0}, {"extensions", {{"EXT_lights_ies", json::object()}}}}}}};
    EXPECT_TRUE(load(extra, d)) << d.format();
    EXPECT_EQ(d.errorCount(), 0) << d.format();
    const std::vector<Diagnostic> clearcoat = naming(d, "KHR_materials_clearcoat");
    ASSERT_EQ(clearcoat.size(), 1u) << d.format();
    EXPECT_EQ(clearcoat[0].severity, Severity::Warning);
    EXPECT_EQ(clearcoat[0].location, "/extensionsUsed/0");
    const std::vector<Diagnostic> ies = naming(d, "EXT_lights_ies");
    ASSERT_EQ(ies.size(), 1u) << d.format();
    EXPECT_EQ(ies[0].location, "/nodes/0/extensions/EXT_lights_ies");
    EXPECT_EQ(naming(d, "KHR_texture_transform").size(), 0u) << d.format();
    EXPECT_EQ(d.warnings, 2) << d.format();
}

TEST(GltfExtensions, SampleModelsNeedNoWarningAboutExtensions) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    // TextureTransformTest declares KHR_texture_transform, which rmsc reads; the others use none.
    for (const char* name : {"TextureTransformTest.gltf", "VertexColorTest.gltf",
                             "TextureSettingsTest.gltf", "TwoSidedPlane.gltf"}) {
        Diagnostics d;
        EXPECT_TRUE(loadGltf(gltfSamples() / name, diskFileSource(), d)) << d.format();
        EXPECT_EQ(naming(d, "extension").size(), 0u) << name << ": " << d.format();
    }
}

TEST(GltfExtensions, DocsListExactlyTheSupportedExtensions) {
    // docs/gltf.md "## Extensions": one "- `NAME`: what rmsc reads of it" line per row of the
    // table, in its order.
    std::ifstream file(std::string(RMSC_TEST_SOURCE_DIR) + "/docs/gltf.md");
    ASSERT_TRUE(file) << "docs/gltf.md is missing";
    std::vector<std::string> listed;
    bool inSection = false;
    for (std::string line; std::getline(file, line);) {
        if (line.rfind("## ", 0) == 0) inSection = line == "## Extensions";
        if (inSection && line.rfind("- `", 0) == 0) listed.push_back(line);
    }
    std::vector<std::string> expected;
    for (const GltfExtensionInfo& e : gltfExtensions())
        expected.push_back("- `" + std::string(e.name) + "`: " + std::string(e.reads));
    EXPECT_EQ(listed, expected);
}
