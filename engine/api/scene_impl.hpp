// What a public Scene holds: its JSON document (what edits change), the scene prepared from it
// (checked, glTF files loaded, SDF compiled), and the identity a Renderer keeps its upload by.
#pragma once

#include "rmsc/scene.hpp"

#include "core/diagnostics.hpp"
#include "prepare/prepared_scene.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace rmsc::api {

struct Scene::Impl {
    std::uint64_t id = 0; // unique in the process
    std::uint64_t revision = 0;
    std::filesystem::path path;
    nlohmann::json document;
    PreparedScene prepared;
    std::vector<Problem> warnings;
};

// The problems of `diagnostics` as the public type (a last one counts those not kept).
std::vector<Problem> toProblems(const Diagnostics& diagnostics);
// Error (BadInput) with every problem of `diagnostics`, its message their lines.
Error badInput(const Diagnostics& diagnostics);

} // namespace rmsc::api
