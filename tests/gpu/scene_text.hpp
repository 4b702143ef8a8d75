// Test helper: a scene written as JSON text in a test, prepared as if it were a file in
// samples/scenes/ (so "../assets/..." mesh paths resolve to the repository's sample assets).
#pragma once

#include "gpu_test_support.hpp"
#include "scene/scene_json.hpp"

#include <stdexcept>
#include <string>

namespace rmsc::test {

inline PreparedScene prepareSceneText(const std::string& json,
                                      ShellMode shellMode = ShellMode::AsScene) {
    Diagnostics diagnostics;
    const std::filesystem::path path =
        std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "samples" / "scenes" / "test-scene.json";
    std::optional<Scene> scene = parseScene(json, path, diagnostics);
    std::optional<PreparedScene> prepared;
    if (scene) prepared = prepareScene(std::move(*scene), diskFileSource(), diagnostics, shellMode);
    EXPECT_TRUE(prepared.has_value()) << diagnostics.format();
    if (!prepared) throw std::runtime_error("cannot prepare the test scene");
    return std::move(*prepared);
}

} // namespace rmsc::test
