// Reading and writing scene files (JSON, versioned; docs/scene-format.md). The reader checks
// every field against the format and the primitive catalogue and reports every problem it
// finds in one pass, each with the file and the JSON pointer of the offending value.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace rmsc {

constexpr int kSceneFormatVersion = 1;

// Parses scene JSON text. `path` names the file in messages and is the base that relative
// mesh paths resolve against. Returns nullopt if any error was found (warnings alone, such as
// unknown keys, still return the scene).
std::optional<Scene> parseScene(std::string_view text, const std::filesystem::path& path,
                                Diagnostics& diagnostics);

// Reads `path` through `files` and parses it.
std::optional<Scene> loadScene(const std::filesystem::path& path, const FileSource& files,
                               Diagnostics& diagnostics);

// Lights given in code (a host's own, drawn with a scene's SDF objects), checked as the reader
// checks a scene's "lights": the same keys, ranges, messages and limit on their number, each
// problem at "/INDEX/KEY" in `file`, and a non-finite number refused. Returns the lights as the
// reader makes them (directions normalized), or nullopt when any is invalid.
std::optional<std::vector<Light>> checkLights(std::span<const Light> lights,
                                              const std::string& file, Diagnostics& diagnostics);

// The scene as JSON text in the same format parseScene reads (round-trips).
std::string sceneToJson(const Scene& scene);

} // namespace rmsc
