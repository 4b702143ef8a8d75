// Scene-file sections about light: one entry of "lights" (directional, point, spot), the
// "shadows" and "ao" objects of "render", and the "environment" section (sky and fog). Readers
// check every field and report problems with JSON pointers; writers produce what the readers
// accept (docs/scene-format.md, "Lights", "Shadows and ambient occlusion", "Environment").
#pragma once

#include "json_reader.hpp"
#include "scene/scene.hpp"

#include <filesystem>

namespace rmsc {

// Reads the light object at `pointer` into `light`.
void readLight(const JsonReader& json, const Json& object, const std::string& pointer,
               Light& light);
// Reads render/shadows, render/ao and render/fxaa (the other render keys are read elsewhere).
void readRenderLighting(const JsonReader& json, const Json& renderObject, RenderSettings& render);
// Reads the "environment" section; image paths are resolved against `sceneFolder`.
void readEnvironment(const JsonReader& json, const Json& object,
                     const std::filesystem::path& sceneFolder, Environment& environment);

// The render keys readRenderLighting understands, for the unknown-key check.
extern const std::vector<std::string> kRenderLightingKeys;

Json lightToJson(const Light& light);
// Adds "shadows", "ao" and "fxaa" to a render object when they differ from "off".
void writeRenderLighting(const RenderSettings& render, Json& renderObject);
// The "environment" section, or null when the scene has none (no sky and no fog).
Json environmentToJson(const Environment& environment);

} // namespace rmsc
