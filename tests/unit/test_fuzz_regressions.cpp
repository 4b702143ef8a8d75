// Inputs the fuzzers once crashed on (tests/fuzz/regressions/): each must now be read without a
// crash, giving a result or diagnostics but never both or neither. Under tools/sanitize.sh
// this also catches any memory error they used to cause.
#include "scene/mesh_asset.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace rmsc;
namespace fs = std::filesystem;

namespace {

const fs::path kRegressions = fs::path(RMSC_TEST_SOURCE_DIR) / "tests/fuzz/regressions";

std::vector<fs::path> inputs(const std::string& fuzzer) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(kRegressions / fuzzer, ec))
        if (entry.is_regular_file()) out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

} // namespace

TEST(FuzzRegressions, SceneInputsAreReadWithoutCrashing) {
    for (const fs::path& path : inputs("scene")) {
        SCOPED_TRACE(path.string());
        Diagnostics d;
        const auto scene = parseScene(read(path), "regression.json", d);
        EXPECT_NE(scene.has_value(), d.hasErrors()) << d.format();
    }
}

// Loads every glTF regression input as the fuzzers serve it (the input itself, other files from
// the samples), with the default budget or with `budget`.
void loadGltfInputs(GltfBudget* budget) {
    for (const fs::path& path : inputs("gltf")) {
        SCOPED_TRACE(path.string());
        const std::string bytes = read(path);
        const fs::path entry = bytes.starts_with("glTF") ? "fuzz/model.glb" : "fuzz/model.gltf";
        const FileSource embedded = embeddedFileSource();
        const FileSource files{[&](const fs::path& p, std::string& error) {
            if (p == entry) return std::optional<std::string>(bytes);
            return embedded.read(fs::path("samples/assets") / p.filename(), error);
        }};
        Diagnostics d;
        GltfBudget left;
        if (budget) left = *budget;
        const auto asset = budget ? loadGltf(entry, files, d, left) : loadGltf(entry, files, d);
        EXPECT_NE(asset.has_value(), d.hasErrors()) << d.format();
    }
}

TEST(FuzzRegressions, GltfInputsAreReadWithoutCrashing) {
    loadGltfInputs(nullptr);
}

// fuzz_gltf_accessors loads what it builds with this budget; its findings are kept here as the
// .glb it built (RMSC_FUZZ_WRITE_GLB) and replayed the same way.
TEST(FuzzRegressions, GltfInputsAreReadWithoutCrashingUnderTheAccessorFuzzersBudget) {
    GltfBudget small;
    small.vertices = 1u << 16;
    small.indices = 1u << 18;
    small.texels = 1u << 20;
    loadGltfInputs(&small);
}
