// Reading and writing lights, shadow / AO settings and the environment (sky, fog) of scene
// files. Spot cone angles follow glTF KHR_lights_punctual (defaults 0 and 45 degrees, outer
// at most 90 degrees, inner below outer).
#include "lighting_json.hpp"

#include "scene/environment_spec.hpp"
#include "scene/render_spec.hpp"

#include "core/limits.hpp"
#include "param_json.hpp"
#include "scene/light_spec.hpp"
#include "transform_json.hpp"

#include <algorithm>

namespace rmsc {
namespace {

std::vector<std::string> lightTypeNames() {
    std::vector<std::string> names;
    for (const LightType type : kLightTypes)
        names.emplace_back(lightTypeName(type));
    return names;
}

const std::vector<std::string> kDirectionalKeys = {
    "type", "name", "direction", "color", "intensity", "shadows", "shadow_softness"};
const std::vector<std::string> kPointKeys = {"type",      "name",  "position", "color",
                                             "intensity", "range", "shadows",  "shadow_softness"};
const std::vector<std::string> kSpotKeys = {
    "type",  "name",    "position",        "direction",   "color",      "intensity",
    "range", "shadows", "shadow_softness", "inner_angle", "outer_angle"};
const std::vector<std::string> kShadowKeys = {"enabled",      "steps",         "softness",
                                              "min_distance", "max_distance",  "map_size",
                                              "pcf_radius",   "normal_offset", "slope_bias"};
const std::vector<std::string> kAoKeys = {"samples", "distance", "strength"};
const std::vector<std::string> kEnvironmentKeys = {"sky", "intensity", "fog"};
const std::vector<std::string> kSkyTypes = [] {
    std::vector<std::string> names;
    for (const SkyTypeName& sky : kSkyTypeNames)
        names.emplace_back(sky.name);
    return names;
}();
const std::vector<std::string> kFogKeys = {"color", "density"};

constexpr int kDefaultAoSamples = 5;

// Reads object[key] as a boolean if present (absent leaves *out).
bool readBoolField(const JsonReader& json, const Json& object, const std::string& pointer,
                   std::string_view key, bool* out) {
    const Json* value = findMember(object, key);
    if (!value) return true;
    if (!value->is_boolean()) {
        json.error(childPointer(pointer, key),
                   "expected true or false, got " + jsonTypeName(*value));
        return false;
    }
    *out = value->get<bool>();
    return true;
}

void readDirection(const JsonReader& json, const Json& object, const std::string& pointer,
                   glm::vec3& direction) {
    if (!readVec3Field(json, object, pointer, "direction", &direction)) return;
    if (direction == glm::vec3(0.0f)) {
        json.error(childPointer(pointer, "direction"),
                   "expected a non-zero direction, got [0, 0, 0]");
    } else {
        direction = normalizedForStorage(direction);
    }
}

// Reads the "sky" object of the environment.
void readSky(const JsonReader& json, const Json& object, const std::string& pointer,
             const std::filesystem::path& sceneFolder, Environment& environment) {
    if (!expectObject(json, object, pointer)) return;
    const Json* type = findMember(object, "type");
    const std::string typePointer = childPointer(pointer, "type");
    if (!type) {
        json.error(pointer, "missing \"type\"; known sky types: " + quotedList(kSkyTypes));
        return;
    }
    const auto name = readString(json, *type, typePointer);
    if (!name) return;
    if (*name == "constant") {
        environment.sky = SkyType::Constant;
        warnUnknownKeys(json, object, pointer, std::vector<std::string>{"type", "color"});
        readColorField(json, object, pointer, "color", &environment.color);
    } else if (*name == "gradient") {
        environment.sky = SkyType::Gradient;
        warnUnknownKeys(json, object, pointer,
                        std::vector<std::string>{"type", "zenith", "horizon", "ground"});
        readColorField(json, object, pointer, "zenith", &environment.zenith);
        readColorField(json, object, pointer, "horizon", &environment.horizon);
        readColorField(json, object, pointer, "ground", &environment.ground);
    } else if (*name == "image") {
        environment.sky = SkyType::Image;
        warnUnknownKeys(json, object, pointer,
                        std::vector<std::string>{"type", "file", "rotation"});
        const Json* file = findMember(object, "file");
        const std::string filePointer = childPointer(pointer, "file");
        if (!file) {
            json.error(pointer, "an image sky needs \"file\" (an equirectangular .hdr image, "
                                "relative to the scene file)");
        } else if (const auto text = readString(json, *file, filePointer)) {
            if (text->empty()) {
                json.error(filePointer, "expected the path of an .hdr image, got \"\"");
            } else {
                environment.imageFile = *text;
                const std::filesystem::path path(*text);
                environment.imagePath =
                    (path.is_absolute() ? path : sceneFolder / path).lexically_normal();
            }
        }
        readNumberField(json, object, pointer, "rotation", &environment.rotationDegrees,
                        numberRange(kSkyRotationRange));
    } else {
        json.error(typePointer,
                   "unknown sky type \"" + *name + "\"; known sky types: " + quotedList(kSkyTypes));
    }
}

} // namespace

const std::vector<std::string> kRenderLightingKeys = {"shadows", "ao", "fxaa"};

void readLight(const JsonReader& json, const Json& object, const std::string& pointer,
               Light& light) {
    const std::vector<std::string>* keys = &kDirectionalKeys;
    if (const Json* type = findMember(object, "type")) {
        const std::string typePointer = childPointer(pointer, "type");
        if (const auto name = readString(json, *type, typePointer)) {
            if (const std::optional<LightType> known = findLightType(*name)) {
                light.type = *known;
                if (light.type == LightType::Point) keys = &kPointKeys;
                if (light.type == LightType::Spot) keys = &kSpotKeys;
            } else {
                json.error(typePointer, "unknown light type \"" + *name +
                                            "\"; known types: " + quotedList(lightTypeNames()));
            }
        }
    } else {
        json.error(pointer, "missing \"type\"; known types: " + quotedList(lightTypeNames()));
    }
    warnUnknownKeys(json, object, pointer, *keys);
    readStringField(json, object, pointer, "name", &light.name);
    if (hasDirection(light.type)) readDirection(json, object, pointer, light.direction);
    if (hasPosition(light.type)) readVec3Field(json, object, pointer, "position", &light.position);
    if (hasRange(light.type))
        readNumberField(json, object, pointer, "range", &light.range,
                        numberRange(kLightRangeRange));
    readColorField(json, object, pointer, "color", &light.color);
    readNumberField(json, object, pointer, "intensity", &light.intensity,
                    numberRange(kLightIntensityRange));
    readBoolField(json, object, pointer, "shadows", &light.castShadows);
    readNumberField(json, object, pointer, "shadow_softness", &light.shadowSoftness,
                    numberRange(kLightShadowSoftnessRange));
    if (hasCone(light.type)) {
        const bool innerOk =
            readNumberField(json, object, pointer, "inner_angle", &light.innerAngleDegrees,
                            numberRange(kSpotInnerAngleRange));
        const bool outerOk =
            readNumberField(json, object, pointer, "outer_angle", &light.outerAngleDegrees,
                            numberRange(kSpotOuterAngleRange));
        if (innerOk && outerOk && !(light.outerAngleDegrees > light.innerAngleDegrees)) {
            json.error(childPointer(pointer, "outer_angle"),
                       "expected \"outer_angle\" > \"inner_angle\" (" +
                           formatNumber(light.innerAngleDegrees) + " degrees), got " +
                           formatNumber(light.outerAngleDegrees));
        }
    }
}

void readRenderLighting(const JsonReader& json, const Json& renderObject, RenderSettings& render) {
    if (const Json* shadows = findMember(renderObject, "shadows")) {
        const std::string pointer = "/render/shadows";
        if (expectObject(json, *shadows, pointer)) {
            ShadowSettings& s = render.shadows;
            s.enabled = true; // writing the object turns shadows on unless it says otherwise
            warnUnknownKeys(json, *shadows, pointer, kShadowKeys);
            readBoolField(json, *shadows, pointer, "enabled", &s.enabled);
            readIntegerField(json, *shadows, pointer, "steps", &s.steps, int(kShadowStepsRange.min),
                             int(kShadowStepsRange.max));
            readNumberField(json, *shadows, pointer, "softness", &s.softness,
                            numberRange(kShadowSoftnessRange));
            const bool minOk =
                readNumberField(json, *shadows, pointer, "min_distance", &s.minDistance,
                                numberRange(kShadowMinDistanceRange));
            const bool maxOk =
                readNumberField(json, *shadows, pointer, "max_distance", &s.maxDistance,
                                numberRange(kShadowMaxDistanceRange));
            if (minOk && maxOk && !(s.maxDistance > s.minDistance)) {
                json.error(childPointer(pointer, "max_distance"),
                           "expected \"max_distance\" > \"min_distance\" (" +
                               formatNumber(s.minDistance) + "), got " +
                               formatNumber(s.maxDistance));
            }
            readIntegerField(json, *shadows, pointer, "map_size", &s.mapSize,
                             int(kShadowMapSizeRange.min), int(kShadowMapSizeRange.max));
            readIntegerField(json, *shadows, pointer, "pcf_radius", &s.pcfRadius,
                             int(kShadowPcfRadiusRange.min), int(kShadowPcfRadiusRange.max));
            readNumberField(json, *shadows, pointer, "normal_offset", &s.normalOffset,
                            numberRange(kShadowNormalOffsetRange));
            readNumberField(json, *shadows, pointer, "slope_bias", &s.slopeBias,
                            numberRange(kShadowSlopeBiasRange));
        }
    }
    if (const Json* ao = findMember(renderObject, "ao")) {
        const std::string pointer = "/render/ao";
        if (expectObject(json, *ao, pointer)) {
            render.ao.samples = kDefaultAoSamples;
            warnUnknownKeys(json, *ao, pointer, kAoKeys);
            readIntegerField(json, *ao, pointer, "samples", &render.ao.samples,
                             int(kAoSamplesRange.min), int(kAoSamplesRange.max));
            readNumberField(json, *ao, pointer, "distance", &render.ao.distance,
                            numberRange(kAoDistanceRange));
            readNumberField(json, *ao, pointer, "strength", &render.ao.strength,
                            numberRange(kAoStrengthRange));
        }
    }
    readBoolField(json, renderObject, "/render", "fxaa", &render.fxaa);
}

void readEnvironment(const JsonReader& json, const Json& object,
                     const std::filesystem::path& sceneFolder, Environment& environment) {
    const std::string pointer = "/environment";
    if (!expectObject(json, object, pointer)) return;
    warnUnknownKeys(json, object, pointer, kEnvironmentKeys);
    if (const Json* sky = findMember(object, "sky"))
        readSky(json, *sky, childPointer(pointer, "sky"), sceneFolder, environment);
    readNumberField(json, object, pointer, "intensity", &environment.intensity,
                    numberRange(kEnvironmentIntensityRange));
    if (const Json* fog = findMember(object, "fog")) {
        const std::string fogPointer = childPointer(pointer, "fog");
        if (expectObject(json, *fog, fogPointer)) {
            warnUnknownKeys(json, *fog, fogPointer, kFogKeys);
            readColorField(json, *fog, fogPointer, "color", &environment.fogColor);
            if (!findMember(*fog, "density")) {
                json.error(fogPointer, "fog needs \"density\" (a number in [0, 10], the "
                                       "extinction per world unit)");
            }
            readNumberField(json, *fog, fogPointer, "density", &environment.fogDensity,
                            numberRange(kFogDensityRange));
        }
    }
}

Json lightToJson(const Light& light) {
    Json out = Json::object();
    out["type"] = std::string(lightTypeName(light.type));
    if (!light.name.empty()) out["name"] = light.name;
    if (hasPosition(light.type)) out["position"] = vec3ToJson(light.position);
    if (hasDirection(light.type)) out["direction"] = vec3ToJson(light.direction);
    out["color"] = vec3ToJson(light.color);
    out["intensity"] = floatToJson(light.intensity);
    if (hasRange(light.type) && light.range > 0.0f) out["range"] = floatToJson(light.range);
    if (hasCone(light.type)) {
        out["inner_angle"] = floatToJson(light.innerAngleDegrees);
        out["outer_angle"] = floatToJson(light.outerAngleDegrees);
    }
    if (!light.castShadows) out["shadows"] = false;
    if (light.shadowSoftness > 0.0f) out["shadow_softness"] = floatToJson(light.shadowSoftness);
    return out;
}

void writeRenderLighting(const RenderSettings& render, Json& renderObject) {
    // Shadows or occlusion turned off keep their numbers in the file where those differ from
    // the defaults ("enabled": false, "samples": 0), so turning them on again gives what they
    // were.
    const ShadowSettings& s = render.shadows;
    const ShadowSettings noShadows;
    const bool shadowNumbers =
        s.steps != noShadows.steps || s.softness != noShadows.softness ||
        s.minDistance != noShadows.minDistance || s.maxDistance != noShadows.maxDistance ||
        s.mapSize != noShadows.mapSize || s.pcfRadius != noShadows.pcfRadius ||
        s.normalOffset != noShadows.normalOffset || s.slopeBias != noShadows.slopeBias;
    if (s.enabled || shadowNumbers) {
        renderObject["shadows"] = {{"steps", s.steps},
                                   {"softness", floatToJson(s.softness)},
                                   {"min_distance", floatToJson(s.minDistance)},
                                   {"max_distance", floatToJson(s.maxDistance)},
                                   {"map_size", s.mapSize},
                                   {"pcf_radius", s.pcfRadius},
                                   {"normal_offset", floatToJson(s.normalOffset)},
                                   {"slope_bias", floatToJson(s.slopeBias)}};
        if (!s.enabled) renderObject["shadows"]["enabled"] = false;
    }
    const AoSettings noAo;
    if (render.ao.samples > 0 || render.ao.distance != noAo.distance ||
        render.ao.strength != noAo.strength) {
        renderObject["ao"] = {{"samples", render.ao.samples},
                              {"distance", floatToJson(render.ao.distance)},
                              {"strength", floatToJson(render.ao.strength)}};
    }
    if (render.fxaa) renderObject["fxaa"] = true;
}

Json environmentToJson(const Environment& environment) {
    if (environment.sky == SkyType::None && environment.fogDensity <= 0.0f) return nullptr;
    Json out = Json::object();
    switch (environment.sky) {
    case SkyType::None:
        break;
    case SkyType::Constant:
        out["sky"] = {{"type", "constant"}, {"color", vec3ToJson(environment.color)}};
        break;
    case SkyType::Gradient:
        out["sky"] = {{"type", "gradient"},
                      {"zenith", vec3ToJson(environment.zenith)},
                      {"horizon", vec3ToJson(environment.horizon)},
                      {"ground", vec3ToJson(environment.ground)}};
        break;
    case SkyType::Image:
        out["sky"] = {{"type", "image"},
                      {"file", environment.imageFile.empty()
                                   ? environment.imagePath.generic_string()
                                   : environment.imageFile},
                      {"rotation", floatToJson(environment.rotationDegrees)}};
        break;
    }
    out["intensity"] = floatToJson(environment.intensity);
    if (environment.fogDensity > 0.0f) {
        out["fog"] = {{"color", vec3ToJson(environment.fogColor)},
                      {"density", floatToJson(environment.fogDensity)}};
    }
    return out;
}

} // namespace rmsc
