// Reading scene files (format version 1, docs/scene-format.md): each section is checked field
// by field against the format and the catalogues (primitives, modifiers, operations, profiles),
// reporting every problem with its JSON pointer and carrying on, so one run shows everything
// wrong with a file. The "sdf" tree is read by sdf_json.cpp.
#include "scene/scene_json.hpp"

#include "core/limits.hpp"
#include "json_reader.hpp"
#include "lighting_json.hpp"
#include "material_texture_json.hpp"
#include "param_json.hpp"
#include "scene/camera_spec.hpp"
#include "scene/light_spec.hpp"
#include "scene/material_spec.hpp"
#include "scene/render_spec.hpp"
#include "sdf_json.hpp"
#include "transform_json.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace rmsc {

bool readMaterialRef(SceneReader& r, const Json& object, const std::string& pointer, int* out) {
    const Json* value = findMember(object, "material");
    if (!value) return true;
    const std::string valuePointer = childPointer(pointer, "material");
    const auto name = readString(r.json, *value, valuePointer);
    if (!name) return false;
    const auto it = r.materialIndex.find(*name);
    if (it != r.materialIndex.end()) {
        *out = it->second;
        return true;
    }
    std::string message = "unknown material \"" + *name + "\"";
    if (r.materialNames.empty()) {
        message += "; the scene defines no materials (add them under \"materials\")";
    } else if (r.unknownMaterialsExplained++ >= limits::kDiagnosticsKept) {
        message += " (" + std::to_string(r.materialNames.size()) + " materials are defined)";
    } else {
        if (auto match = closeMatch(*name, r.materialNames)) {
            message += "; did you mean \"" + *match +
                       "\"? (known materials: " + quotedList(r.materialNames) + ")";
        } else {
            message += "; known materials: " + quotedList(r.materialNames);
        }
    }
    r.json.error(valuePointer, message);
    return false;
}

std::filesystem::path resolveMeshPath(const std::filesystem::path& sceneFolder,
                                      const std::string& file) {
    const std::filesystem::path path(file);
    if (path.is_absolute()) return path.lexically_normal();
    return (sceneFolder / path).lexically_normal();
}

namespace {

constexpr int kMaxLights = limits::kLights;

const std::vector<std::string> kRootKeys = {"version", "camera", "render",      "materials",
                                            "lights",  "meshes", "environment", "sdf"};
const std::vector<std::string> kCameraKeys = {"position", "target", "up",         "fov",
                                              "near",     "far",    "projection", "ortho_height"};
const std::vector<std::string> kRenderKeys = {"max_steps",  "max_distance", "surface_epsilon",
                                              "background", "ambient",      "exposure"};
const std::vector<std::string> kMaterialKeys = {"base_color", "metallic", "roughness", "emissive"};
const std::vector<std::string> kMeshKeys = {"name",       "file",  "position", "rotation",
                                            "quaternion", "scale", "material", "animation",
                                            "time",       "scene"};

// "animation" (a glTF animation's name, or its index as text: "0") and "time" (seconds, >= 0) of a
// mesh.
void readMeshAnimation(const SceneReader& r, const Json& object, const std::string& pointer,
                       MeshInstance& mesh) {
    if (const Json* animation = findMember(object, "animation")) {
        const std::string at = childPointer(pointer, "animation");
        if (const auto text = readString(r.json, *animation, at)) {
            if (text->empty())
                r.json.error(at, "expected the name or index of an animation of the glTF file, "
                                 "got \"\"");
            mesh.animation = *text;
        }
    }
    float time = 0.0f;
    if (readNumberField(r.json, object, pointer, "time", &time, NumberRange::atLeast(0.0)))
        mesh.time = time;
    if (findMember(object, "time") && !findMember(object, "animation"))
        r.json.warning(childPointer(pointer, "time"),
                       "\"time\" without \"animation\" has no effect (the rest pose is drawn)");
}

void readCamera(const SceneReader& r, const Json& object, Camera& camera) {
    const std::string pointer = "/camera";
    if (!expectObject(r.json, object, pointer)) return;
    warnUnknownKeys(r.json, object, pointer, kCameraKeys);
    const bool positionOk = readVec3Field(r.json, object, pointer, "position", &camera.position);
    const bool targetOk = readVec3Field(r.json, object, pointer, "target", &camera.target);
    const bool upOk = readVec3Field(r.json, object, pointer, "up", &camera.up);
    readNumberField(r.json, object, pointer, "fov", &camera.fovYDegrees,
                    numberRange(kCameraFovRange));
    const bool nearOk = readNumberField(r.json, object, pointer, "near", &camera.nearPlane,
                                        numberRange(kCameraNearRange));
    const bool farOk = readNumberField(r.json, object, pointer, "far", &camera.farPlane,
                                       numberRange(kCameraFarRange));
    if (nearOk && farOk && !(camera.farPlane > camera.nearPlane)) {
        r.json.error(childPointer(pointer, "far"), "expected \"far\" > \"near\" (" +
                                                       formatNumber(camera.nearPlane) + "), got " +
                                                       formatNumber(camera.farPlane));
    }
    if (const Json* projection = findMember(object, "projection")) {
        const std::string at = childPointer(pointer, "projection");
        if (const auto name = readString(r.json, *projection, at)) {
            if (const std::optional<CameraProjection> known = findCameraProjection(*name))
                camera.projection = *known;
            else
                r.json.error(at, "unknown projection \"" + *name +
                                     "\"; expected \"perspective\" or \"orthographic\"");
        }
    }
    readNumberField(r.json, object, pointer, "ortho_height", &camera.orthoHeight,
                    numberRange(kCameraOrthoHeightRange));
    if (findMember(object, "ortho_height") && camera.projection != CameraProjection::Orthographic)
        r.json.warning(childPointer(pointer, "ortho_height"),
                       "\"ortho_height\" has no effect without \"projection\": \"orthographic\"");
    if (!positionOk || !targetOk || !upOk) return;
    if (const std::optional<CameraProblem> problem = cameraFrameProblem(camera))
        r.json.error(childPointer(pointer, problem->key), problem->message);
}

void readRender(const SceneReader& r, const Json& object, RenderSettings& render) {
    const std::string pointer = "/render";
    if (!expectObject(r.json, object, pointer)) return;
    std::vector<std::string> renderKeys = kRenderKeys;
    renderKeys.insert(renderKeys.end(), kRenderLightingKeys.begin(), kRenderLightingKeys.end());
    warnUnknownKeys(r.json, object, pointer, renderKeys);
    readRenderLighting(r.json, object, render);
    readIntegerField(r.json, object, pointer, "max_steps", &render.maxSteps,
                     int(kMaxStepsRange.min), int(kMaxStepsRange.max));
    readNumberField(r.json, object, pointer, "max_distance", &render.maxDistance,
                    numberRange(kMaxDistanceRange));
    readNumberField(r.json, object, pointer, "surface_epsilon", &render.surfaceEpsilon,
                    numberRange(kSurfaceEpsilonRange));
    readColorField(r.json, object, pointer, "background", &render.background);
    readColorField(r.json, object, pointer, "ambient", &render.ambient);
    readNumberField(r.json, object, pointer, "exposure", &render.exposure,
                    numberRange(kExposureRange));
}

void readMaterials(SceneReader& r, const Json& object, std::vector<Material>& materials) {
    const std::string pointer = "/materials";
    if (!expectObject(r.json, object, pointer)) return;
    if (object.size() > std::size_t(limits::kMaterials)) {
        r.json.error(pointer, "the scene has " + std::to_string(object.size()) +
                                  " materials; at most " + std::to_string(limits::kMaterials) +
                                  " are supported (the limit)");
        return;
    }
    for (const auto& [name, value] : object.items()) {
        const std::string materialPointer = childPointer(pointer, name);
        // Known even when its fields are wrong, so references to it do not add errors.
        r.materialIndex.emplace(name, int(r.materialNames.size()));
        r.materialNames.push_back(name);
        Material material;
        material.name = name;
        if (name.empty()) r.json.error(materialPointer, "a material name must not be empty");
        if (expectObject(r.json, value, materialPointer)) {
            std::vector<std::string> known = kMaterialKeys;
            known.insert(known.end(), materialTextureKeys().begin(), materialTextureKeys().end());
            warnUnknownKeys(r.json, value, materialPointer, known);
            readMaterialTextures(r.json, value, materialPointer, r.sceneFolder, material);
            readColorField(r.json, value, materialPointer, "base_color", &material.baseColor);
            readNumberField(r.json, value, materialPointer, "metallic", &material.metallic,
                            numberRange(kMetallicRange));
            readNumberField(r.json, value, materialPointer, "roughness", &material.roughness,
                            numberRange(kRoughnessRange));
            readColorField(r.json, value, materialPointer, "emissive", &material.emissive);
        }
        materials.push_back(std::move(material));
    }
}

void readLights(const SceneReader& r, const Json& array, std::vector<Light>& lights) {
    const std::string pointer = "/lights";
    if (!array.is_array()) {
        r.json.error(pointer, "expected an array of lights, got " + jsonTypeName(array));
        return;
    }
    if (array.size() > std::size_t(kMaxLights)) {
        r.json.error(pointer, "the scene has " + std::to_string(array.size()) +
                                  " lights; at most " + std::to_string(kMaxLights) +
                                  " are supported (the limit)");
    }
    for (std::size_t i = 0; i < array.size(); ++i) {
        const Json& object = array[i];
        const std::string lightPointer = childPointer(pointer, i);
        if (!expectObject(r.json, object, lightPointer)) continue;
        Light light;
        readLight(r.json, object, lightPointer, light);
        lights.push_back(std::move(light));
    }
}

void readMeshes(SceneReader& r, const Json& array, std::vector<MeshInstance>& meshes) {
    const std::string pointer = "/meshes";
    if (!array.is_array()) {
        r.json.error(pointer, "expected an array of meshes, got " + jsonTypeName(array));
        return;
    }
    if (array.size() > std::size_t(limits::kMeshInstances)) {
        r.json.error(pointer, "the scene has " + std::to_string(array.size()) +
                                  " meshes; at most " + std::to_string(limits::kMeshInstances) +
                                  " are supported (the limit)");
        return;
    }
    for (std::size_t i = 0; i < array.size(); ++i) {
        const Json& object = array[i];
        const std::string meshPointer = childPointer(pointer, i);
        if (!expectObject(r.json, object, meshPointer)) continue;
        warnUnknownKeys(r.json, object, meshPointer, kMeshKeys);
        MeshInstance mesh;
        mesh.pointer = meshPointer;
        if (const Json* file = findMember(object, "file")) {
            const std::string filePointer = childPointer(meshPointer, "file");
            if (const auto text = readString(r.json, *file, filePointer)) {
                if (text->empty()) {
                    r.json.error(filePointer, "expected the path of a glTF file, got \"\"");
                } else {
                    mesh.file = *text;
                    mesh.path = resolveMeshPath(r.sceneFolder, *text);
                    mesh.name = std::filesystem::path(*text).stem().string();
                }
            }
        } else {
            r.json.error(meshPointer, "missing \"file\" (the path of a glTF file, relative to "
                                      "the scene file)");
        }
        readStringField(r.json, object, meshPointer, "name", &mesh.name);
        readTransform(r.json, object, meshPointer, mesh.transform);
        readMaterialRef(r, object, meshPointer, &mesh.materialOverride);
        readMeshAnimation(r, object, meshPointer, mesh);
        // Which scene of the glTF file (checked against the file when it loads).
        readIntegerField(r.json, object, meshPointer, "scene", &mesh.gltfScene, 0,
                         std::numeric_limits<int>::max());
        meshes.push_back(std::move(mesh));
    }
}

// Reads "version"; returns false when the rest of the file must not be read as version 1.
bool readVersion(const SceneReader& r, const Json& root, Scene& scene) {
    const Json* version = findMember(root, "version");
    if (!version) {
        r.json.error(
            "", "missing \"version\"; add \"version\": " + std::to_string(kSceneFormatVersion) +
                    " at the top of the file (the format this file is written in)");
        return true; // probably a version 1 file: check the rest too
    }
    if (!version->is_number_integer()) {
        r.json.error("/version",
                     "expected the integer " + std::to_string(kSceneFormatVersion) + ", got " +
                         (version->is_number() ? version->dump() : jsonTypeName(*version)));
        return false;
    }
    // nlohmann reads non-negative integers as unsigned, negative ones as signed.
    const bool negative = !version->is_number_unsigned();
    const auto number = negative ? 0 : version->get<std::uint64_t>();
    if (!negative && number > std::uint64_t(kSceneFormatVersion)) {
        r.json.error("/version", "this file is format version " + version->dump() +
                                     "; this rmsc reads version " +
                                     std::to_string(kSceneFormatVersion) + " — upgrade rmsc");
        return false;
    }
    if (negative || number < std::uint64_t(kSceneFormatVersion)) {
        // Version 1 is the first format; nothing older exists to migrate from.
        r.json.error("/version",
                     "there is no format version " + version->dump() +
                         "; this rmsc reads version 1, the first. To migrate, write \"version\": " +
                         std::to_string(kSceneFormatVersion) +
                         " and check the file against docs/scene-format.md");
        return false;
    }
    scene.version = int(number);
    return true;
}

std::optional<Scene> readScene(const Json& root, const std::filesystem::path& path,
                               const JsonReader& json) {
    if (!root.is_object()) {
        json.error("", "expected a scene object {\"version\": 1, ...} at the top level, got " +
                           jsonTypeName(root));
        return std::nullopt;
    }
    SceneReader r{json, path.parent_path(), {}, {}, 0, 0, false};
    Scene scene;
    scene.file = path;
    if (!readVersion(r, root, scene)) return std::nullopt;
    warnUnknownKeys(json, root, "", kRootKeys);
    // Materials first: the other sections refer to them by name.
    if (const Json* v = findMember(root, "materials")) readMaterials(r, *v, scene.materials);
    if (const Json* v = findMember(root, "camera")) readCamera(r, *v, scene.camera);
    if (const Json* v = findMember(root, "render")) readRender(r, *v, scene.render);
    if (const Json* v = findMember(root, "lights")) readLights(r, *v, scene.lights);
    if (const Json* v = findMember(root, "meshes")) readMeshes(r, *v, scene.meshes);
    if (const Json* v = findMember(root, "environment"))
        readEnvironment(json, *v, r.sceneFolder, scene.environment);
    if (const Json* v = findMember(root, "sdf")) {
        scene.sdf.emplace();
        readSdfNode(r, *v, "/sdf", 0, *scene.sdf);
    }
    return scene;
}

} // namespace

std::optional<Scene> parseScene(std::string_view text, const std::filesystem::path& path,
                                Diagnostics& diagnostics) {
    const JsonReader json{path.string(), &diagnostics};
    const int errorsBefore = diagnostics.errorCount();
    if (text.size() > limits::kSceneFileBytes) {
        json.error("", "the scene file is " + std::to_string(text.size()) + " bytes; at most " +
                           std::to_string(limits::kSceneFileBytes) + " are supported (the limit)");
        return std::nullopt;
    }
    try {
        const std::optional<Json> root = parseJsonText(text, json);
        if (!root) return std::nullopt;
        std::optional<Scene> scene = readScene(*root, path, json);
        if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
        return scene;
    } catch (const std::exception& e) {
        // Out of memory, or a bug: report it rather than crash the editor.
        json.error("", std::string("cannot read the scene: ") + e.what());
    }
    return std::nullopt;
}

std::optional<Scene> loadScene(const std::filesystem::path& path, const FileSource& files,
                               Diagnostics& diagnostics) {
    std::string why;
    std::optional<std::string> text;
    try {
        text = files.read(path, why);
    } catch (const std::exception& e) {
        why = e.what();
    }
    if (!text) {
        diagnostics.error(path.string(), "", "cannot read scene file: " + why);
        return std::nullopt;
    }
    return parseScene(*text, path, diagnostics);
}

namespace {

// A light given in code as the JSON object a scene file would hold, its values as they are (the
// writer's lightToJson makes values valid; here an invalid value must reach the reader). A
// number that JSON cannot hold is reported here and gives nullopt.
std::optional<Json> codeLightJson(const JsonReader& json, const Light& light,
                                  const std::string& pointer) {
    bool finite = true;
    const auto number = [&](const std::string& key, float value) {
        if (!std::isfinite(value)) {
            json.error(childPointer(pointer, key),
                       std::string("expected a finite number, got ") + (std::isnan(value) ? "nan"
                                                                        : value > 0       ? "inf"
                                                                                    : "-inf"));
            finite = false;
        }
        return Json(double(value));
    };
    const auto vector = [&](const std::string& key, const glm::vec3& value) {
        Json out = Json::array();
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(value[i])) {
                json.error(childPointer(childPointer(pointer, key), std::size_t(i)),
                           std::string("expected a finite number, got ") +
                               (std::isnan(value[i]) ? "nan"
                                : value[i] > 0       ? "inf"
                                                     : "-inf"));
                finite = false;
            }
            out.push_back(double(value[i]));
        }
        return out;
    };
    Json object = Json::object();
    object["type"] = std::string(lightTypeName(light.type));
    if (!light.name.empty()) object["name"] = light.name;
    if (hasDirection(light.type)) object["direction"] = vector("direction", light.direction);
    if (hasPosition(light.type)) object["position"] = vector("position", light.position);
    object["color"] = vector("color", light.color);
    object["intensity"] = number("intensity", light.intensity);
    if (hasRange(light.type) && light.range != 0.0f) object["range"] = number("range", light.range);
    if (hasCone(light.type)) {
        object["inner_angle"] = number("inner_angle", light.innerAngleDegrees);
        object["outer_angle"] = number("outer_angle", light.outerAngleDegrees);
    }
    object["shadows"] = light.castShadows;
    if (!(light.shadowSoftness < 0.0f))
        object["shadow_softness"] = number("shadow_softness", light.shadowSoftness);
    if (!finite) return std::nullopt;
    return object;
}

} // namespace

std::optional<std::vector<Light>> checkLights(std::span<const Light> lights,
                                              const std::string& file, Diagnostics& diagnostics) {
    const JsonReader json{file, &diagnostics};
    const int errorsBefore = diagnostics.errorCount();
    if (lights.size() > std::size_t(kMaxLights))
        json.error("", "there are " + std::to_string(lights.size()) + " lights; at most " +
                           std::to_string(kMaxLights) + " are supported (the limit)");
    std::vector<Light> read;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::string pointer = childPointer("", i);
        const std::optional<Json> object = codeLightJson(json, lights[i], pointer);
        if (!object) continue;
        Light light;
        readLight(json, *object, pointer, light);
        read.push_back(std::move(light));
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    return read;
}

} // namespace rmsc
