// Test helper: the SDF program of a scene whose "sdf" is the given JSON text (no file on disk,
// default compile options). A parse or compile error fails the calling test.
#pragma once

#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"

#include <gtest/gtest.h>

#include <string>

namespace rmsc::test {

inline SdfProgram compileSdfText(const std::string& sdfJson) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene =
        parseScene(R"({"version": 1, "sdf": )" + sdfJson + "}", "t.json", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.format();
    if (!scene || !scene->sdf) return {};
    std::optional<SdfProgram> program = compileSdf(*scene->sdf, 0, "t.json", diagnostics);
    EXPECT_TRUE(program) << diagnostics.format();
    return program ? std::move(*program) : SdfProgram{};
}

} // namespace rmsc::test
