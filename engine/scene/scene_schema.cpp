// Generating docs/scene.schema.json (see scene_schema.hpp).
//
// Each kind of JSON object in the format is an ObjectDef below: where it lives in a scene
// (a probe context), the keys that select its kind ({"type": "spot"}) and a schema per key.
// The catalogue rows (primitives, modifiers, profiles, profile solids, operation and blend
// names) become ObjectDefs and names here by themselves. When the reader learns a key or a name
// outside the catalogues, `rmsc schema` and the unit test SceneSchema.* say which ObjectDef or
// family lacks it; add a row there. After either, refresh the shipped file with
//   rmsc schema > docs/scene.schema.json
#include "scene/scene_schema.hpp"

#include "core/limits.hpp"
#include "json_reader.hpp"
#include "param_json.hpp"
#include "scene/camera_spec.hpp"
#include "scene/environment_spec.hpp"
#include "scene/light_spec.hpp"
#include "scene/material_spec.hpp"
#include "scene/render_spec.hpp"
#include "scene/scene_json.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"
#include "transform_json.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace rmsc {
namespace {

constexpr double kBig = 1.0e4; // the format's bound on lengths, as the catalogue's
// A key no reader knows, far (by edit distance) from every real key, so the reader's warning
// lists all known keys rather than suggesting one.
const std::string kProbeKey = "zzzz_schema_probe_zzzz";

// ---- Value schemas ----

Json described(Json schema, const std::string& description) {
    schema["description"] = description;
    return schema;
}

// A number schema with the bounds of `range` (the reader's own NumberRange type).
Json number(const NumberRange& range) {
    Json schema = {{"type", "number"}};
    if (std::isfinite(range.min))
        schema[range.minExclusive ? "exclusiveMinimum" : "minimum"] = floatToJson(float(range.min));
    if (std::isfinite(range.max))
        schema[range.maxExclusive ? "exclusiveMaximum" : "maximum"] = floatToJson(float(range.max));
    return schema;
}

Json numbers(int count, const NumberRange& range = {}) {
    return {{"type", "array"}, {"items", number(range)}, {"minItems", count}, {"maxItems", count}};
}

Json integer(int lo, int hi) {
    return {{"type", "integer"}, {"minimum", lo}, {"maximum", hi}};
}
Json integers(int count, int lo, int hi) {
    return {
        {"type", "array"}, {"items", integer(lo, hi)}, {"minItems", count}, {"maxItems", count}};
}
Json string() {
    return {{"type", "string"}};
}
Json boolean() {
    return {{"type", "boolean"}};
}
Json path(const std::string& what) {
    return described({{"type", "string"}, {"minLength", 1}}, what + ", relative to the scene file");
}
Json ref(const std::string& def) {
    return {{"$ref", "#/$defs/" + def}};
}

Json color() {
    return {{"oneOf", Json::array({described(numbers(3, NumberRange::atLeast(0.0)), "linear RGB"),
                                   {{"type", "string"},
                                    {"pattern", "^#[0-9a-fA-F]{6}$"},
                                    {"description", "sRGB, hexadecimal"}}})}};
}

// A string whose valid values the generator reads from the reader's error message.
Json readerNames(const std::string& description) {
    return {{"type", "string"}, {"enum", "(probed)"}, {"description", description}};
}

Json enumOf(const std::set<std::string>& names) {
    Json values = Json::array();
    for (const std::string& name : names)
        values.push_back(name);
    return values;
}

// A string naming a catalogue row.
Json namesOf(const std::vector<std::string>& names, const std::string& description) {
    return {{"type", "string"},
            {"enum", enumOf({names.begin(), names.end()})},
            {"description", description}};
}

// A catalogue parameter (sdf/param_spec.hpp): its type, range, default and description.
Json paramSchema(const SdfParamSpec& spec) {
    const NumberRange range = numberRange(spec);
    Json schema;
    switch (spec.type) {
    case ParamType::Number:
        schema = number(range);
        break;
    case ParamType::Integer:
        schema = integer(int(range.min), int(range.max));
        break;
    case ParamType::Vec2:
        schema = numbers(2, range);
        break;
    case ParamType::Vec3:
        schema = numbers(3, range);
        break;
    case ParamType::IVec3:
        schema = integers(3, int(range.min), int(range.max));
        break;
    case ParamType::Bool:
        schema = boolean();
        break;
    case ParamType::Axes:
        schema = {{"type", "string"}, {"pattern", "^[xyz]{1,3}$"}};
        break;
    case ParamType::Axis:
        schema = {{"type", "string"}, {"enum", {"x", "y", "z"}}};
        break;
    case ParamType::Points:
        schema = {{"type", "array"},
                  {"items", numbers(2, range)},
                  {"minItems", kMinPolygonPoints},
                  {"maxItems", kMaxPolygonPoints}};
        break;
    }
    if (!spec.required) schema["default"] = paramDefaultToJson(spec);
    return described(schema, std::string(spec.description));
}

// ---- The format's objects ----

struct Key {
    std::string name;
    Json schema;
};

struct ObjectDef {
    std::string def;   // name in $defs ("" = the root)
    Json context;      // a scene holding the object, without it
    std::string where; // JSON pointer of the object in `context`
    Json base;         // keys that make the reader read the object as this kind
    std::vector<Key> keys;
    std::vector<std::string> required;
    std::string description;
};

std::vector<Key> transformKeys() {
    const NumberRange positive = NumberRange::above(0.0);
    return {
        {"position", described(numbers(3), "metres, relative to the parent")},
        {"rotation", described(numbers(3), "Euler angles in degrees, applied x, then y, then z")},
        {"quaternion", described(numbers(4), "rotation [x, y, z, w], non-zero")},
        {"scale", {{"oneOf", Json::array({number(positive), numbers(3, positive)})}}},
    };
}

std::vector<Key> nodeKeys() {
    std::vector<Key> keys = {
        {"name", string()},
        {"material", described(string(), "the name of a material in \"materials\"")},
        {"modifiers", {{"type", "array"}, {"maxItems", 16}, {"items", ref("modifier")}}},
        {"cut",
         described(boolean(), "subtracts this node from the combination of its siblings that "
                              "are not cut, wherever it stands among them (before or after)")},
        {"shell", {{"oneOf", Json::array({boolean(), ref("shell")})}}},
    };
    for (Key& key : transformKeys())
        keys.push_back(std::move(key));
    return keys;
}

std::vector<Key> plus(std::vector<Key> keys, std::vector<Key> more) {
    for (Key& key : more)
        keys.push_back(std::move(key));
    return keys;
}

// A material texture: a file name, or an object with the file and its mapping.
Json textureRef(const std::string& def) {
    return {{"oneOf", Json::array({path("an image file"), ref(def)})}};
}

std::vector<Key> textureKeys(bool normalMap) {
    std::vector<Key> keys = {
        {"file", path("an image file")},
        {"scale", number(numberRange(kTextureScaleRange))},
        {"sharpness", number(numberRange(kTextureSharpnessRange))},
    };
    if (normalMap) keys.push_back({"strength", number(numberRange(kNormalStrengthRange))});
    return keys;
}

const Json kScene = {{"version", kSceneFormatVersion}};
Json sceneWith(const char* key, Json value) {
    Json scene = kScene;
    scene[key] = std::move(value);
    return scene;
}

std::vector<ObjectDef> objectDefs() {
    const NumberRange positiveLength = NumberRange::openClosed(0.0, kBig);
    const std::vector<Key> lightCommon = {
        {"type", string()},
        {"name", string()},
        {"color", color()},
        {"intensity", number(numberRange(kLightIntensityRange))},
        {"shadows", described(boolean(), "whether the light casts shadows")},
        {"shadow_softness", number(numberRange(kLightShadowSoftnessRange))},
    };
    const Key direction = {"direction", described(numbers(3), "the direction light travels")};
    const Key position = {"position", numbers(3)};
    const Key range = {"range", described(number(numberRange(kLightRangeRange)), "metres")};
    const Json sdfShape = sceneWith("sdf", {{"shape", "sphere"}});
    const Json extrusion = sceneWith("sdf", {{"shape", "extrusion"}});
    const Json environment = sceneWith("environment", Json::object());
    std::vector<ObjectDef> defs = {
        {"",
         {},
         "",
         kScene,
         {{"version", described({{"const", kSceneFormatVersion}}, "format version")},
          {"camera", ref("camera")},
          {"render", ref("render")},
          {"materials",
           {{"type", "object"},
            {"maxProperties", limits::kMaterials},
            {"propertyNames", {{"minLength", 1}}},
            {"additionalProperties", ref("material")}}},
          {"lights", {{"type", "array"}, {"maxItems", limits::kLights}, {"items", ref("light")}}},
          {"meshes",
           {{"type", "array"}, {"maxItems", limits::kMeshInstances}, {"items", ref("mesh")}}},
          {"environment", ref("environment")},
          {"sdf", ref("node")}},
         {"version"},
         ""},
        {"camera",
         kScene,
         "/camera",
         Json::object(),
         {{"position", numbers(3)},
          {"target", numbers(3)},
          {"up", numbers(3)},
          {"fov", described(number(numberRange(kCameraFovRange)), "vertical, degrees")},
          {"near", number(numberRange(kCameraNearRange))},
          {"far", described(number(numberRange(kCameraFarRange)), "greater than near")},
          {"projection", described({{"type", "string"}, {"enum", {"perspective", "orthographic"}}},
                                   "perspective (the default) or orthographic: parallel rays")},
          {"ortho_height", described(number(numberRange(kCameraOrthoHeightRange)),
                                     "orthographic: the height of the view, world units")}},
         {},
         "a pinhole camera, or an orthographic one"},
        {"render",
         kScene,
         "/render",
         Json::object(),
         {{"max_steps", integer(int(kMaxStepsRange.min), int(kMaxStepsRange.max))},
          {"max_distance", number(numberRange(kMaxDistanceRange))},
          {"surface_epsilon", number(numberRange(kSurfaceEpsilonRange))},
          {"background", color()},
          {"ambient", color()},
          {"exposure", number(numberRange(kExposureRange))},
          {"shadows", ref("shadows")},
          {"ao", ref("ao")},
          {"fxaa", boolean()}},
         {},
         "ray marching and shading settings"},
        {"shadows",
         kScene,
         "/render/shadows",
         Json::object(),
         {{"enabled", boolean()},
          {"steps", integer(int(kShadowStepsRange.min), int(kShadowStepsRange.max))},
          {"softness", number(numberRange(kShadowSoftnessRange))},
          {"min_distance", number(numberRange(kShadowMinDistanceRange))},
          {"max_distance", number(numberRange(kShadowMaxDistanceRange))},
          {"map_size", integer(int(kShadowMapSizeRange.min), int(kShadowMapSizeRange.max))},
          {"pcf_radius", integer(int(kShadowPcfRadiusRange.min), int(kShadowPcfRadiusRange.max))},
          {"normal_offset", number(numberRange(kShadowNormalOffsetRange))},
          {"slope_bias", number(numberRange(kShadowSlopeBiasRange))}},
         {},
         "shadow settings"},
        {"ao",
         kScene,
         "/render/ao",
         Json::object(),
         {{"samples", integer(int(kAoSamplesRange.min), int(kAoSamplesRange.max))},
          {"distance", number(numberRange(kAoDistanceRange))},
          {"strength", number(numberRange(kAoStrengthRange))}},
         {},
         "ambient occlusion settings"},
        {"material",
         kScene,
         "/materials/m",
         Json::object(),
         {{"base_color", color()},
          {"metallic", number(numberRange(kMetallicRange))},
          {"roughness", number(numberRange(kRoughnessRange))},
          {"emissive", color()},
          {"base_color_texture", textureRef("texture")},
          {"normal_texture", textureRef("normal_texture")},
          {"roughness_texture", textureRef("texture")}},
         {},
         "a glTF-style metallic-roughness material"},
        {"texture",
         kScene,
         "/materials/m/base_color_texture",
         {{"file", "a.png"}},
         textureKeys(false),
         {"file"},
         "an image file mapped onto the surface"},
        {"normal_texture",
         kScene,
         "/materials/m/normal_texture",
         {{"file", "a.png"}},
         textureKeys(true),
         {"file"},
         "a tangent-space normal map"},
        {"light_directional",
         kScene,
         "/lights/0",
         {{"type", "directional"}},
         plus(lightCommon, {direction}),
         {"type"},
         "a light from infinitely far away"},
        {"light_point",
         kScene,
         "/lights/0",
         {{"type", "point"}},
         plus(lightCommon, {position, range}),
         {"type"},
         "a light shining from a point in every direction"},
        {"light_spot",
         kScene,
         "/lights/0",
         {{"type", "spot"}},
         plus(lightCommon, {position,
                            direction,
                            range,
                            {"inner_angle", number(numberRange(kSpotInnerAngleRange))},
                            {"outer_angle", described(number(numberRange(kSpotOuterAngleRange)),
                                                      "degrees, greater than inner_angle")}}),
         {"type"},
         "a light shining from a point in a cone"},
        {"mesh",
         kScene,
         "/meshes/0",
         {{"file", "a.gltf"}},
         plus({{"name", string()},
               {"file", path("a .gltf or .glb file")},
               {"material", described(string(), "overrides the glTF's materials")},
               {"animation",
                described(string(), "the glTF animation shown, by name or by index as text "
                                    "(\"0\"); without it the rest pose")},
               {"time", described(number(NumberRange::atLeast(0.0)),
                                  "seconds into \"animation\" (default 0)")},
               {"scene", described(Json{{"type", "integer"}, {"minimum", 0}},
                                   "the index of the glTF file's scene drawn (default: the "
                                   "file's default scene)")}},
              transformKeys()),
         {"file"},
         "a placement of a glTF file"},
        {"environment",
         kScene,
         "/environment",
         Json::object(),
         {{"sky", ref("sky")},
          {"intensity", number(numberRange(kEnvironmentIntensityRange))},
          {"fog", ref("fog")}},
         {},
         "sky and fog"},
        {"sky_constant",
         environment,
         "/environment/sky",
         {{"type", "constant"}},
         {{"type", string()}, {"color", color()}},
         {"type"},
         "one colour in every direction"},
        {"sky_gradient",
         environment,
         "/environment/sky",
         {{"type", "gradient"}},
         {{"type", string()}, {"zenith", color()}, {"horizon", color()}, {"ground", color()}},
         {"type"},
         "colours blended from the zenith to the horizon to the ground"},
        {"sky_image",
         environment,
         "/environment/sky",
         {{"type", "image"}},
         {{"type", string()},
          {"file", path("an equirectangular .hdr image")},
          {"rotation", described(number(numberRange(kSkyRotationRange)), "degrees")}},
         {"type", "file"},
         "an equirectangular image"},
        {"fog",
         environment,
         "/environment/fog",
         {{"density", 0.1}},
         {{"color", color()},
          {"density", described(number(numberRange(kFogDensityRange)), "extinction per metre")}},
         {"density"},
         "exponential fog"},
        {"group",
         kScene,
         "/sdf",
         {{"op", "smooth_union"}, {"smoothness", 0.1}, {"children", Json::array()}},
         plus(nodeKeys(),
              {{"op", namesOf(operationNames(), "how the children combine")},
               {"smoothness", described(number(numberRange(smoothnessParam())),
                                        "metres; required by the smooth_, chamfer_ and round_ "
                                        "ops")},
               {"blend", namesOf(blendNames(), "the smooth-minimum curve of the smooth_ ops")},
               {"children", {{"type", "array"}, {"items", ref("node")}}}}),
         {},
         "a group of nodes combined by an operation"},
        {"shell",
         sdfShape,
         "/sdf/shell",
         {{"proxy", "box"}},
         {{"proxy",
           readerNames("the proxy mesh: the bounds' box, a sphere around them, or a glTF")},
          {"bound", described(numbers(3, positiveLength),
                              "half extents in the node's frame: the content is clipped to them")},
          {"mesh", path("a glTF file, the proxy when \"proxy\" is \"mesh\"")}},
         {},
         "draws the node through a proxy mesh (mesh-shell mode)"},
    };
    // Insert the catalogue rows where they have always been in the file: the profile solids and
    // the profiles before "shell", the modifiers after it.
    const auto shell =
        std::find_if(defs.begin(), defs.end(), [](const ObjectDef& d) { return d.def == "shell"; });
    std::vector<ObjectDef> profiles;
    for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
        std::vector<Key> keys =
            plus(nodeKeys(), {{"shape", string()}, {"profile", ref("profile")}});
        keys.push_back({std::string(solid.param.spec.key), paramSchema(solid.param.spec)});
        profiles.push_back({"shape_" + std::string(solid.name),
                            kScene,
                            "/sdf",
                            {{"shape", std::string(solid.name)}},
                            keys,
                            {"shape", "profile"},
                            std::string(solid.description)});
    }
    for (const ProfileSpec& spec : profileCatalogue()) {
        std::vector<Key> keys = {{"type", string()}};
        std::vector<std::string> required = {"type"};
        for (const ProfileParam& param : spec.params) {
            keys.push_back({std::string(param.spec.key), paramSchema(param.spec)});
            if (param.spec.required) required.emplace_back(param.spec.key);
        }
        profiles.push_back({"profile_" + std::string(spec.name),
                            extrusion,
                            "/sdf/profile",
                            {{"type", std::string(spec.name)}},
                            keys,
                            required,
                            std::string(spec.description)});
    }
    std::vector<ObjectDef> modifiers;
    for (const ModifierSpec& spec : modifierCatalogue()) {
        std::vector<Key> keys = {{"type", string()}};
        std::vector<std::string> required = {"type"};
        for (const ModifierParam& param : spec.params) {
            keys.push_back({std::string(param.spec.key), paramSchema(param.spec)});
            if (param.spec.required) required.emplace_back(param.spec.key);
        }
        modifiers.push_back({"modifier_" + std::string(spec.name),
                             sdfShape,
                             "/sdf/modifiers/0",
                             {{"type", std::string(spec.name)}},
                             keys,
                             required,
                             std::string(spec.description)});
    }
    const std::ptrdiff_t at = shell - defs.begin();
    defs.insert(defs.begin() + at + 1, modifiers.begin(), modifiers.end());
    defs.insert(defs.begin() + at, profiles.begin(), profiles.end());
    // One shape per catalogue primitive, its parameters with the catalogue's ranges.
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        std::vector<Key> keys = plus(nodeKeys(), {{"shape", string()}});
        for (const ParamSpec& param : spec.params) {
            const NumberRange paramRange = NumberRange::closed(param.minValue, param.maxValue);
            Json schema = param.components == 1 ? number(paramRange) : numbers(3, paramRange);
            schema["default"] = param.components == 1
                                    ? floatToJson(param.value[0])
                                    : vec3ToJson({param.value[0], param.value[1], param.value[2]});
            schema["description"] = std::string(param.description);
            keys.push_back({std::string(param.name), schema});
        }
        defs.push_back({"shape_" + std::string(spec.name),
                        kScene,
                        "/sdf",
                        {{"shape", std::string(spec.name)}},
                        keys,
                        {"shape"},
                        std::string(spec.description)});
    }
    return defs;
}

// Objects told apart by one key: the family's schema is a choice of its members.
struct Family {
    std::string def;                      // "light"
    std::string discriminator;            // "type"
    std::string prefix;                   // members are the ObjectDefs named prefix + value
    std::vector<std::string> alsoChoices; // other $defs in the choice ("group" for nodes)
};

const Family kFamilies[] = {
    {"light", "type", "light_", {}},        {"sky", "type", "sky_", {}},
    {"profile", "type", "profile_", {}},    {"modifier", "type", "modifier_", {}},
    {"node", "shape", "shape_", {"group"}},
};

// ---- Probing the reader ----

std::vector<Diagnostic> probe(const ObjectDef& def, const Json& object) {
    Json scene = def.context.is_null() ? Json::object() : def.context;
    if (def.where.empty()) {
        scene = object;
    } else {
        scene[Json::json_pointer(def.where)] = object;
    }
    Diagnostics diagnostics;
    parseScene(scene.dump(), "probe.json", diagnostics);
    return diagnostics.items;
}

// The quoted names in a message, without `except`.
std::set<std::string> quotedNames(const std::string& message, const std::string& except) {
    std::set<std::string> names;
    std::size_t at = 0;
    while ((at = message.find('"', at)) != std::string::npos) {
        const std::size_t end = message.find('"', at + 1);
        if (end == std::string::npos) break;
        std::string name = message.substr(at + 1, end - at - 1);
        if (name != except) names.insert(name);
        at = end + 1;
    }
    return names;
}

// The keys the reader knows in objects of this kind, from its warning about kProbeKey.
std::optional<std::set<std::string>> probeKeys(const ObjectDef& def) {
    Json object = def.base;
    object[kProbeKey] = 0;
    const std::string pointer = childPointer(def.where, kProbeKey);
    for (const Diagnostic& d : probe(def, object)) {
        const std::size_t list = d.message.find("known keys: ");
        if (d.location == pointer && list != std::string::npos)
            return quotedNames(d.message.substr(list), kProbeKey);
    }
    return std::nullopt;
}

// The names the reader accepts for `key`, from its error about an unknown name.
std::optional<std::set<std::string>> probeNames(const ObjectDef& def, const std::string& key) {
    Json object = def.base;
    object[key] = kProbeKey;
    const std::string pointer = childPointer(def.where, key);
    for (const Diagnostic& d : probe(def, object)) {
        if (d.location == pointer && d.severity == Severity::Error) {
            std::set<std::string> names = quotedNames(d.message, kProbeKey);
            if (!names.empty()) return names;
        }
    }
    return std::nullopt;
}

std::string joined(const std::set<std::string>& names) {
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "\"" : ", \"") + name + "\"";
    return out;
}

// The object schema of `def`, checked against the reader; problems are appended.
Json objectSchema(const ObjectDef& def, std::vector<std::string>& problems) {
    const std::string where = def.def.empty() ? "the root" : "$defs/" + def.def;
    const std::string site = "engine/scene/scene_schema.cpp (" + where + ")";
    std::set<std::string> described;
    Json properties = Json::object();
    for (const Key& key : def.keys) {
        described.insert(key.name);
        Json schema = key.schema;
        if (schema.contains("enum") && schema["enum"] == "(probed)") {
            const auto names = probeNames(def, key.name);
            if (!names) {
                problems.push_back("cannot read the valid values of \"" + key.name + "\" in " +
                                   where + " from the reader's error; describe them in " + site);
                schema.erase("enum");
            } else {
                schema["enum"] = enumOf(*names);
            }
        }
        properties[key.name] = schema;
    }
    // A selecting key given as a plain string is fixed to its value ({"const": "spot"}).
    for (auto it = def.base.begin(); it != def.base.end(); ++it) {
        if (described.count(it.key()) && it->is_string() && properties[it.key()] == string())
            properties[it.key()] = {{"const", *it}};
    }
    const auto known = probeKeys(def);
    if (!known) {
        problems.push_back("the reader did not warn about an unknown key in " + where + " at " +
                           def.where + "; fix the probe context in " + site);
    } else {
        for (const std::string& key : *known)
            if (!described.count(key))
                problems.push_back("the reader knows \"" + key + "\" in " + where +
                                   " but the schema does not: describe it in " + site);
        for (const std::string& key : described)
            if (!known->count(key))
                problems.push_back("the schema describes \"" + key + "\" in " + where +
                                   " but the reader does not know it (known: " + joined(*known) +
                                   "): remove it from " + site);
    }
    Json schema = Json::object();
    if (!def.description.empty()) schema["description"] = def.description;
    schema["type"] = "object";
    schema["properties"] = properties;
    if (!def.required.empty()) schema["required"] = def.required;
    // Unknown keys are warnings in the reader; editors show them as problems.
    schema["additionalProperties"] = false;
    if (properties.contains("rotation") && properties.contains("quaternion"))
        schema["not"] = {{"required", {"rotation", "quaternion"}}};
    return schema;
}

} // namespace

SceneSchema generateSceneSchema() {
    SceneSchema result;
    Json schema = {
        {"$schema", "https://json-schema.org/draft/2020-12/schema"},
        {"$id", "https://rmsc.invalid/scene.schema.json"},
        {"title", "rmsc scene file, format version " + std::to_string(kSceneFormatVersion)},
        {"description", "Generated by `rmsc schema` from the scene reader and the catalogues; see "
                        "docs/scene-format.md. Do not edit by hand."},
    };
    const std::vector<ObjectDef> defs = objectDefs();
    Json all = Json::object();
    for (const ObjectDef& def : defs) {
        Json object = objectSchema(def, result.problems);
        if (def.def.empty()) {
            for (auto& [key, value] : object.items())
                if (key != "description") schema[key] = value;
        } else {
            all[def.def] = std::move(object);
        }
    }
    // Groups are told from shapes by "children" or "op".
    all["group"]["anyOf"] = Json::array({{{"required", {"children"}}}, {{"required", {"op"}}}});

    Json ordered = Json::object();
    for (const Family& family : kFamilies) {
        // The family's members must be exactly the names the reader accepts.
        const auto member = std::find_if(defs.begin(), defs.end(), [&](const ObjectDef& d) {
            return d.def.starts_with(family.prefix);
        });
        std::set<std::string> described;
        Json choices = Json::array();
        for (const std::string& other : family.alsoChoices)
            choices.push_back(ref(other));
        for (const ObjectDef& def : defs) {
            if (!def.def.starts_with(family.prefix)) continue;
            described.insert(def.def.substr(family.prefix.size()));
            choices.push_back(ref(def.def));
        }
        const auto names =
            member == defs.end() ? std::nullopt : probeNames(*member, family.discriminator);
        if (!names) {
            result.problems.push_back("cannot read the valid \"" + family.discriminator +
                                      "\" names of $defs/" + family.def + " from the reader");
        } else {
            for (const std::string& name : *names)
                if (!described.count(name))
                    result.problems.push_back(
                        "the reader knows " + family.def + " " + family.discriminator + " \"" +
                        name + "\" but the schema does not: add an ObjectDef \"" + family.prefix +
                        name + "\" in engine/scene/scene_schema.cpp");
            for (const std::string& name : described)
                if (!names->count(name))
                    result.problems.push_back("the schema describes " + family.def + " \"" + name +
                                              "\" but the reader does not know it");
        }
        ordered[family.def] = {{"oneOf", choices}};
    }
    for (auto& [key, value] : all.items())
        ordered[key] = std::move(value);
    schema["$defs"] = std::move(ordered);
    result.text = schema.dump(2) + "\n";
    return result;
}

} // namespace rmsc
