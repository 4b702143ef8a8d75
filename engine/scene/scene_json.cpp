// Reading scene files (format version 1, docs/scene-format.md): each section is checked field
// by field against the format and the primitive catalogue, reporting every problem with its
// JSON pointer and carrying on, so one run shows everything wrong with a file.
#include "scene/scene_json.hpp"

#include "scene/json_reader.hpp"
#include "scene/transform_json.hpp"

#include <algorithm>
#include <exception>

namespace rmsc {
namespace {

constexpr int kMaxLights = 64;
constexpr int kMaxSdfGroupDepth = 128;
constexpr int kMaxSdfNodes = 100000;

const std::vector<std::string> kRootKeys = {"version", "camera", "render", "materials",
                                            "lights",  "meshes", "sdf"};
const std::vector<std::string> kCameraKeys = {"position", "target", "up", "fov", "near", "far"};
const std::vector<std::string> kRenderKeys = {"max_steps",  "max_distance", "surface_epsilon",
                                              "background", "ambient",      "exposure"};
const std::vector<std::string> kMaterialKeys = {"base_color", "metallic", "roughness", "emissive"};
const std::vector<std::string> kLightKeys = {"type", "name", "direction", "color", "intensity"};
const std::vector<std::string> kLightTypes = {"directional"};
const std::vector<std::string> kMeshKeys = {"name",       "file",  "position", "rotation",
                                            "quaternion", "scale", "material"};
const std::vector<std::string> kGroupKeys = {"name",       "op",       "smoothness",
                                             "children",   "position", "rotation",
                                             "quaternion", "scale",    "material"};
const std::vector<std::string> kShapeCommonKeys = {"name",       "shape", "position", "rotation",
                                                   "quaternion", "scale", "material"};

struct OpName {
    SdfOp op;
    const char* name;
    bool smooth;
};
constexpr OpName kOps[] = {
    {SdfOp::Union, "union", false},
    {SdfOp::Subtraction, "subtraction", false},
    {SdfOp::Intersection, "intersection", false},
    {SdfOp::SmoothUnion, "smooth_union", true},
    {SdfOp::SmoothSubtraction, "smooth_subtraction", true},
    {SdfOp::SmoothIntersection, "smooth_intersection", true},
};

// Everything the section readers share.
struct SceneReader {
    JsonReader json;
    std::filesystem::path sceneFolder;
    std::vector<std::string> materialNames; // Scene::materials order
    int sdfNodes = 0;                       // nodes read so far, pre-order
    bool sdfNodeLimitReported = false;
};

// Resolves a "material" reference to an index into Scene::materials; absent leaves *out.
bool readMaterialRef(const SceneReader& r, const Json& object, const std::string& pointer,
                     int* out) {
    const Json* value = findMember(object, "material");
    if (!value) return true;
    const std::string valuePointer = childPointer(pointer, "material");
    const auto name = readString(r.json, *value, valuePointer);
    if (!name) return false;
    const auto it = std::find(r.materialNames.begin(), r.materialNames.end(), *name);
    if (it != r.materialNames.end()) {
        *out = int(it - r.materialNames.begin());
        return true;
    }
    std::string message = "unknown material \"" + *name + "\"";
    if (r.materialNames.empty()) {
        message += "; the scene defines no materials (add them under \"materials\")";
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

void readCamera(const SceneReader& r, const Json& object, Camera& camera) {
    const std::string pointer = "/camera";
    if (!expectObject(r.json, object, pointer)) return;
    warnUnknownKeys(r.json, object, pointer, kCameraKeys);
    const bool positionOk = readVec3Field(r.json, object, pointer, "position", &camera.position);
    const bool targetOk = readVec3Field(r.json, object, pointer, "target", &camera.target);
    const bool upOk = readVec3Field(r.json, object, pointer, "up", &camera.up);
    readNumberField(r.json, object, pointer, "fov", &camera.fovYDegrees,
                    NumberRange::open(0.0, 180.0));
    const bool nearOk = readNumberField(r.json, object, pointer, "near", &camera.nearPlane,
                                        NumberRange::above(0.0));
    const bool farOk =
        readNumberField(r.json, object, pointer, "far", &camera.farPlane, NumberRange::above(0.0));
    if (nearOk && farOk && !(camera.farPlane > camera.nearPlane)) {
        r.json.error(childPointer(pointer, "far"), "expected \"far\" > \"near\" (" +
                                                       formatNumber(camera.nearPlane) + "), got " +
                                                       formatNumber(camera.farPlane));
    }
    if (!positionOk || !targetOk || !upOk) return;
    const glm::vec3 view = camera.target - camera.position;
    if (view == glm::vec3(0.0f)) {
        r.json.error(childPointer(pointer, "target"),
                     "the camera's \"target\" equals its \"position\"; it must look somewhere");
        return;
    }
    const float upLength = glm::length(camera.up);
    const float sine = upLength > 0.0f
                           ? glm::length(glm::cross(camera.up / upLength, glm::normalize(view)))
                           : 0.0f;
    if (!(sine > 1e-4f)) {
        r.json.error(childPointer(pointer, "up"),
                     "expected an \"up\" vector that is non-zero and not parallel to the view "
                     "direction (target - position)");
    }
}

void readRender(const SceneReader& r, const Json& object, RenderSettings& render) {
    const std::string pointer = "/render";
    if (!expectObject(r.json, object, pointer)) return;
    warnUnknownKeys(r.json, object, pointer, kRenderKeys);
    readIntegerField(r.json, object, pointer, "max_steps", &render.maxSteps, 1, 4096);
    readNumberField(r.json, object, pointer, "max_distance", &render.maxDistance,
                    NumberRange::openClosed(0.0, 1e5));
    readNumberField(r.json, object, pointer, "surface_epsilon", &render.surfaceEpsilon,
                    NumberRange::openClosed(0.0, 1.0));
    readColorField(r.json, object, pointer, "background", &render.background);
    readColorField(r.json, object, pointer, "ambient", &render.ambient);
    readNumberField(r.json, object, pointer, "exposure", &render.exposure, NumberRange::above(0.0));
}

void readMaterials(SceneReader& r, const Json& object, std::vector<Material>& materials) {
    const std::string pointer = "/materials";
    if (!expectObject(r.json, object, pointer)) return;
    for (const auto& [name, value] : object.items()) {
        const std::string materialPointer = childPointer(pointer, name);
        // Known even when its fields are wrong, so references to it do not add errors.
        r.materialNames.push_back(name);
        Material material;
        material.name = name;
        if (name.empty()) r.json.error(materialPointer, "a material name must not be empty");
        if (expectObject(r.json, value, materialPointer)) {
            warnUnknownKeys(r.json, value, materialPointer, kMaterialKeys);
            readColorField(r.json, value, materialPointer, "base_color", &material.baseColor);
            readNumberField(r.json, value, materialPointer, "metallic", &material.metallic,
                            NumberRange::closed(0.0, 1.0));
            readNumberField(r.json, value, materialPointer, "roughness", &material.roughness,
                            NumberRange::closed(0.0, 1.0));
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
        warnUnknownKeys(r.json, object, lightPointer, kLightKeys);
        Light light;
        if (const Json* type = findMember(object, "type")) {
            const std::string typePointer = childPointer(lightPointer, "type");
            if (const auto name = readString(r.json, *type, typePointer)) {
                if (*name == "directional") {
                    light.type = LightType::Directional;
                } else {
                    r.json.error(typePointer, "unknown light type \"" + *name +
                                                  "\"; known types: " + quotedList(kLightTypes));
                }
            }
        } else {
            r.json.error(lightPointer, "missing \"type\"; known types: " + quotedList(kLightTypes));
        }
        readStringField(r.json, object, lightPointer, "name", &light.name);
        if (readVec3Field(r.json, object, lightPointer, "direction", &light.direction)) {
            if (light.direction == glm::vec3(0.0f)) {
                r.json.error(childPointer(lightPointer, "direction"),
                             "expected a non-zero direction, got [0, 0, 0]");
            } else {
                light.direction = normalizedForStorage(light.direction);
            }
        }
        readColorField(r.json, object, lightPointer, "color", &light.color);
        readNumberField(r.json, object, lightPointer, "intensity", &light.intensity,
                        NumberRange::atLeast(0.0));
        lights.push_back(std::move(light));
    }
}

std::filesystem::path resolveMeshPath(const std::filesystem::path& sceneFolder,
                                      const std::string& file) {
    const std::filesystem::path path(file);
    if (path.is_absolute()) return path.lexically_normal();
    return (sceneFolder / path).lexically_normal();
}

void readMeshes(const SceneReader& r, const Json& array, std::vector<MeshInstance>& meshes) {
    const std::string pointer = "/meshes";
    if (!array.is_array()) {
        r.json.error(pointer, "expected an array of meshes, got " + jsonTypeName(array));
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
        meshes.push_back(std::move(mesh));
    }
}

void readSdfNode(SceneReader& r, const Json& object, const std::string& pointer, int groupDepth,
                 SdfNode& node);

void readShapeParams(SceneReader& r, const Json& object, const std::string& pointer,
                     const PrimitiveSpec& spec, SdfNode& node) {
    node.primitive = spec.id;
    node.params = defaultParams(spec);
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
        const ParamSpec& param = spec.params[i];
        const Json* value = findMember(object, param.name);
        if (!value) continue;
        const std::string paramPointer = childPointer(pointer, param.name);
        const NumberRange range = NumberRange::closed(param.minValue, param.maxValue);
        float* out = node.params.data() + paramOffset(spec, int(i));
        if (param.components == 1) {
            if (const auto v = readNumber(r.json, *value, paramPointer, range)) *out = *v;
        } else {
            float v[3];
            if (readNumbers(r.json, *value, paramPointer, 3, v, range)) std::copy(v, v + 3, out);
        }
    }
}

void readShape(SceneReader& r, const Json& object, const std::string& pointer, SdfNode& node) {
    node.isGroup = false;
    const std::string shapePointer = childPointer(pointer, "shape");
    const auto name = readString(r.json, *findMember(object, "shape"), shapePointer);
    if (!name) {
        warnUnknownKeys(r.json, object, pointer, kShapeCommonKeys);
        return;
    }
    const PrimitiveSpec* spec = findPrimitive(*name);
    std::vector<std::string> known = kShapeCommonKeys;
    if (spec) {
        for (const ParamSpec& param : spec->params)
            known.emplace_back(param.name);
        readShapeParams(r, object, pointer, *spec, node);
    } else {
        std::vector<std::string> shapes;
        for (const PrimitiveSpec& candidate : primitiveCatalogue())
            shapes.emplace_back(candidate.name);
        r.json.error(shapePointer, "unknown shape \"" + *name + "\"; known shapes: " +
                                       quotedList(sortedByDistance(*name, shapes)));
    }
    // Parameter names of an unknown shape cannot be checked.
    if (spec) warnUnknownKeys(r.json, object, pointer, known);
}

void readGroup(SceneReader& r, const Json& object, const std::string& pointer, int groupDepth,
               SdfNode& node) {
    node.isGroup = true;
    warnUnknownKeys(r.json, object, pointer, kGroupKeys);
    if (const Json* op = findMember(object, "op")) {
        const std::string opPointer = childPointer(pointer, "op");
        if (const auto name = readString(r.json, *op, opPointer)) {
            const auto it = std::find_if(std::begin(kOps), std::end(kOps),
                                         [&](const OpName& o) { return o.name == *name; });
            if (it != std::end(kOps)) {
                node.op = it->op;
            } else {
                std::vector<std::string> names;
                for (const OpName& o : kOps)
                    names.emplace_back(o.name);
                r.json.error(opPointer, "unknown op \"" + *name + "\"; valid ops: " +
                                            quotedList(sortedByDistance(*name, names)));
            }
        }
    }
    const OpName& op = kOps[std::size_t(node.op)];
    const Json* smoothness = findMember(object, "smoothness");
    if (op.smooth) {
        if (smoothness) {
            readNumberField(r.json, object, pointer, "smoothness", &node.smoothness,
                            NumberRange::above(0.0));
        } else {
            r.json.error(pointer, std::string("op \"") + op.name +
                                      "\" needs \"smoothness\" (a number > 0, in world units)");
        }
    } else if (smoothness) {
        r.json.warning(childPointer(pointer, "smoothness"),
                       std::string("\"smoothness\" is ignored by op \"") + op.name +
                           "\"; use a smooth_ op to blend");
    }
    if (groupDepth > kMaxSdfGroupDepth) {
        r.json.error(pointer, "SDF groups are nested more than " +
                                  std::to_string(kMaxSdfGroupDepth) + " levels deep (the limit)");
        return;
    }
    const Json* children = findMember(object, "children");
    if (!children) return;
    const std::string childrenPointer = childPointer(pointer, "children");
    if (!children->is_array()) {
        r.json.error(childrenPointer, "expected an array of nodes, got " + jsonTypeName(*children));
        return;
    }
    node.children.reserve(children->size());
    for (std::size_t i = 0; i < children->size() && !r.sdfNodeLimitReported; ++i) {
        node.children.emplace_back();
        readSdfNode(r, (*children)[i], childPointer(childrenPointer, i), groupDepth,
                    node.children.back());
    }
}

void readSdfNode(SceneReader& r, const Json& object, const std::string& pointer, int groupDepth,
                 SdfNode& node) {
    node.pointer = pointer;
    if (++r.sdfNodes > kMaxSdfNodes) {
        r.json.error(pointer, "the SDF tree has more than " + std::to_string(kMaxSdfNodes) +
                                  " nodes (the limit)");
        r.sdfNodeLimitReported = true;
        return;
    }
    if (!expectObject(r.json, object, pointer)) return;
    readStringField(r.json, object, pointer, "name", &node.name);
    readTransform(r.json, object, pointer, node.transform);
    readMaterialRef(r, object, pointer, &node.material);
    const bool isShape = object.contains("shape");
    const bool isGroup = object.contains("children") || object.contains("op");
    if (isShape && isGroup) {
        r.json.error(pointer, "a node is either a shape (\"shape\") or a group (\"children\", "
                              "\"op\"), not both");
    } else if (isShape) {
        readShape(r, object, pointer, node);
    } else if (isGroup) {
        readGroup(r, object, pointer, groupDepth + 1, node);
    } else {
        r.json.error(pointer, "a node needs \"shape\" (a primitive) or \"children\" (a group "
                              "of nodes)");
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
        r.json.error("/version", "there is no format version " + version->dump() +
                                     "; this rmsc reads version " +
                                     std::to_string(kSceneFormatVersion));
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
    SceneReader r{json, path.parent_path(), {}, 0, false};
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

} // namespace rmsc
