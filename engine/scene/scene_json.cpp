// Reading scene files (format version 1, docs/scene-format.md): each section is checked field
// by field against the format and the catalogues (primitives, modifiers, operations, profiles),
// reporting every problem with its JSON pointer and carrying on, so one run shows everything
// wrong with a file.
#include "scene/scene_json.hpp"

#include "core/limits.hpp"
#include "json_reader.hpp"
#include "lighting_json.hpp"
#include "material_texture_json.hpp"
#include "param_json.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"
#include "transform_json.hpp"

#include <algorithm>
#include <exception>

namespace rmsc {
namespace {

constexpr int kMaxLights = limits::kLights;
constexpr int kMaxSdfGroupDepth = limits::kSdfGroupDepth;
constexpr int kMaxSdfNodes = limits::kSdfNodes;

const std::vector<std::string> kRootKeys = {"version", "camera", "render",      "materials",
                                            "lights",  "meshes", "environment", "sdf"};
const std::vector<std::string> kCameraKeys = {"position", "target", "up", "fov", "near", "far"};
const std::vector<std::string> kRenderKeys = {"max_steps",  "max_distance", "surface_epsilon",
                                              "background", "ambient",      "exposure"};
const std::vector<std::string> kMaterialKeys = {"base_color", "metallic", "roughness", "emissive"};
const std::vector<std::string> kMeshKeys = {"name",       "file",  "position", "rotation",
                                            "quaternion", "scale", "material"};
const std::vector<std::string> kGroupKeys = {
    "name",       "op",    "smoothness", "blend",     "children", "position", "rotation",
    "quaternion", "scale", "material",   "modifiers", "cut",      "shell"};
const std::vector<std::string> kShapeCommonKeys = {"name",       "shape", "position", "rotation",
                                                   "quaternion", "scale", "material", "modifiers",
                                                   "cut",        "shell"};
const std::vector<std::string> kShellKeys = {"proxy", "bound", "mesh"};
const std::vector<std::string> kShellProxies = {"box", "sphere", "mesh"};

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
    // Normalizing a float vector squares its components: from about 1.8e19 on they overflow.
    if (!std::isfinite(glm::length(view))) {
        r.json.error(childPointer(pointer, "target"),
                     "target - position is too long for float arithmetic (its length overflows "
                     "to infinity); expected \"target\" and \"position\" less than 1e19 apart");
        return;
    }
    const float upLength = glm::length(camera.up);
    if (!std::isfinite(upLength)) {
        r.json.error(childPointer(pointer, "up"),
                     "the \"up\" vector is too long for float arithmetic (its length overflows "
                     "to infinity); expected components below 1e19, e.g. [0, 1, 0]");
        return;
    }
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
    std::vector<std::string> renderKeys = kRenderKeys;
    renderKeys.insert(renderKeys.end(), kRenderLightingKeys.begin(), kRenderLightingKeys.end());
    warnUnknownKeys(r.json, object, pointer, renderKeys);
    readRenderLighting(r.json, object, render);
    readIntegerField(r.json, object, pointer, "max_steps", &render.maxSteps, 1,
                     limits::kMarchSteps);
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
    if (object.size() > std::size_t(limits::kMaterials)) {
        r.json.error(pointer, "the scene has " + std::to_string(object.size()) +
                                  " materials; at most " + std::to_string(limits::kMaterials) +
                                  " are supported (the limit)");
        return;
    }
    for (const auto& [name, value] : object.items()) {
        const std::string materialPointer = childPointer(pointer, name);
        // Known even when its fields are wrong, so references to it do not add errors.
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
        Light light;
        readLight(r.json, object, lightPointer, light);
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

constexpr int kMaxModifiers = limits::kSdfModifiers; // per node

// Reports a catalogue row's problems at their keys (and elements) of the object at `pointer`.
void reportProblems(const SceneReader& r, const std::string& pointer,
                    const std::vector<ParamProblem>& problems) {
    for (const ParamProblem& problem : problems) {
        std::string at = childPointer(pointer, problem.key);
        if (problem.element >= 0) at = childPointer(at, std::size_t(problem.element));
        r.json.error(at, problem.message);
    }
}

// A modifier: its parameters as its catalogue row describes them, then the row's own checks.
void readModifier(const SceneReader& r, const Json& object, const std::string& pointer,
                  SdfModifier& m) {
    m.pointer = pointer;
    const std::vector<std::string> names = modifierNames();
    const Json* type = findMember(object, "type");
    if (!type) {
        r.json.error(pointer, "missing \"type\"; known modifiers: " + quotedList(names));
        return;
    }
    const std::string typePointer = childPointer(pointer, "type");
    const auto name = readString(r.json, *type, typePointer);
    if (!name) return;
    const ModifierSpec* spec = findModifier(*name);
    if (!spec) {
        r.json.error(typePointer, "unknown modifier \"" + *name + "\"; known modifiers: " +
                                      quotedList(sortedByDistance(*name, names)));
        return;
    }
    m = defaultModifier(spec->type);
    m.pointer = pointer;
    std::vector<std::string> known = {"type"};
    for (const ModifierParam& param : spec->params)
        known.emplace_back(param.spec.key);
    warnUnknownKeys(r.json, object, pointer, known);
    unsigned readOk = 0;
    for (std::size_t i = 0; i < spec->params.size(); ++i) {
        const ModifierParam& param = spec->params[i];
        const bool ok = std::visit(
            [&](auto field) { return readParam(r.json, object, pointer, param.spec, m.*field); },
            param.field);
        if (ok) readOk |= 1u << i;
    }
    if (!spec->check) return;
    std::vector<ParamProblem> problems;
    spec->check(m, readOk, problems);
    reportProblems(r, pointer, problems);
}

void readModifiers(const SceneReader& r, const Json& object, const std::string& pointer,
                   SdfNode& node) {
    const Json* modifiers = findMember(object, "modifiers");
    if (!modifiers) return;
    const std::string listPointer = childPointer(pointer, "modifiers");
    if (!modifiers->is_array()) {
        r.json.error(listPointer,
                     "expected an array of modifiers, got " + jsonTypeName(*modifiers));
        return;
    }
    if (modifiers->size() > std::size_t(kMaxModifiers)) {
        r.json.error(listPointer, "a node has " + std::to_string(modifiers->size()) +
                                      " modifiers; at most " + std::to_string(kMaxModifiers) +
                                      " are supported (the limit)");
        return;
    }
    for (std::size_t i = 0; i < modifiers->size(); ++i) {
        const std::string modifierPointer = childPointer(listPointer, i);
        if (!expectObject(r.json, (*modifiers)[i], modifierPointer)) continue;
        SdfModifier m;
        readModifier(r, (*modifiers)[i], modifierPointer, m);
        node.modifiers.push_back(m);
    }
}

// A profile: its parameters as its catalogue row describes them, then the row's own checks.
void readProfile(const SceneReader& r, const Json& object, const std::string& pointer,
                 SdfProfile& profile) {
    if (!expectObject(r.json, object, pointer)) return;
    const std::vector<std::string> names = profileNames();
    const Json* type = findMember(object, "type");
    if (!type) {
        r.json.error(pointer, "missing \"type\"; profile types: " + quotedList(names));
        return;
    }
    const std::string typePointer = childPointer(pointer, "type");
    const auto name = readString(r.json, *type, typePointer);
    if (!name) return;
    const ProfileSpec* spec = findProfile(*name);
    if (!spec) {
        r.json.error(typePointer, "unknown profile type \"" + *name + "\"; profile types: " +
                                      quotedList(sortedByDistance(*name, names)));
        return;
    }
    profile.type = spec->type;
    std::vector<std::string> known = {"type"};
    for (const ProfileParam& param : spec->params)
        known.emplace_back(param.spec.key);
    warnUnknownKeys(r.json, object, pointer, known);
    unsigned readOk = 0;
    for (std::size_t i = 0; i < spec->params.size(); ++i) {
        const ProfileParam& param = spec->params[i];
        const bool ok = std::visit(
            [&](auto field) {
                setDefault(param.spec, profile.*field);
                return readParam(r.json, object, pointer, param.spec, profile.*field);
            },
            param.field);
        if (ok) readOk |= 1u << i;
    }
    if (!spec->check) return;
    std::vector<ParamProblem> problems;
    spec->check(profile, readOk, problems);
    reportProblems(r, pointer, problems);
}

// "extrusion" and "revolution": a 2D profile turned into a solid.
void readProfileShape(const SceneReader& r, const Json& object, const std::string& pointer,
                      const ProfileSolidSpec& solid, SdfNode& node) {
    SdfProfile profile;
    profile.solid = solid.solid;
    std::vector<std::string> known = kShapeCommonKeys;
    known.emplace_back("profile");
    known.emplace_back(solid.param.spec.key);
    warnUnknownKeys(r.json, object, pointer, known);
    if (const Json* p = findMember(object, "profile")) {
        readProfile(r, *p, childPointer(pointer, "profile"), profile);
    } else {
        r.json.error(pointer, "missing \"profile\" (the 2D shape to " + std::string(solid.verb) +
                                  "; types: " + quotedList(profileNames()) + ")");
    }
    std::visit(
        [&](auto field) {
            setDefault(solid.param.spec, profile.*field);
            readParam(r.json, object, pointer, solid.param.spec, profile.*field);
        },
        solid.param.field);
    node.profile = std::move(profile);
}

void readShape(SceneReader& r, const Json& object, const std::string& pointer, SdfNode& node) {
    node.isGroup = false;
    const std::string shapePointer = childPointer(pointer, "shape");
    const auto name = readString(r.json, *findMember(object, "shape"), shapePointer);
    if (!name) {
        warnUnknownKeys(r.json, object, pointer, kShapeCommonKeys);
        return;
    }
    if (const ProfileSolidSpec* solid = findProfileSolid(*name)) {
        readProfileShape(r, object, pointer, *solid, node);
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
        for (const ProfileSolidSpec& solid : profileSolidCatalogue())
            shapes.emplace_back(solid.name);
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
            if (const OperationSpec* spec = findOperation(*name)) {
                node.op = spec->op;
            } else {
                r.json.error(opPointer, "unknown op \"" + *name + "\"; valid ops: " +
                                            quotedList(sortedByDistance(*name, operationNames())));
            }
        }
    }
    const std::string opName(operationSpec(node.op).name);
    const Json* smoothness = findMember(object, "smoothness");
    if (takesSmoothness(node.op)) {
        if (smoothness) {
            readNumberField(r.json, object, pointer, "smoothness", &node.smoothness,
                            NumberRange::above(0.0));
        } else {
            r.json.error(pointer, "op \"" + opName +
                                      "\" needs \"smoothness\" (a number > 0, in world units)");
        }
    } else if (smoothness) {
        r.json.warning(childPointer(pointer, "smoothness"), "\"smoothness\" is ignored by op \"" +
                                                                opName +
                                                                "\"; use a smooth_ op to blend");
    }
    if (const Json* blend = findMember(object, "blend")) {
        const std::string blendPointer = childPointer(pointer, "blend");
        if (!takesBlend(node.op)) {
            r.json.warning(blendPointer, "\"blend\" is ignored by op \"" + opName +
                                             "\"; only the smooth_ ops blend");
        } else if (const auto name = readString(r.json, *blend, blendPointer)) {
            const auto spec = std::find_if(blendCatalogue().begin(), blendCatalogue().end(),
                                           [&](const BlendSpec& b) { return b.name == *name; });
            if (spec != blendCatalogue().end()) {
                node.blend = spec->blend;
            } else {
                r.json.error(blendPointer, "unknown blend \"" + *name +
                                               "\"; valid blends: " + quotedList(blendNames()));
            }
        }
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

// "shell": true, or {"proxy": "box" | "sphere" | "mesh", "bound": [x, y, z], "mesh": "file"}.
void readShell(const SceneReader& r, const Json& value, const std::string& pointer, SdfNode& node) {
    SdfShell shell;
    shell.pointer = pointer;
    if (value.is_boolean()) {
        if (value.get<bool>()) node.shell = shell;
        return;
    }
    if (!value.is_object()) {
        r.json.error(pointer, "expected true, false or an object with \"proxy\", \"bound\" and "
                              "\"mesh\", got " +
                                  jsonTypeName(value));
        return;
    }
    warnUnknownKeys(r.json, value, pointer, kShellKeys);
    if (const Json* proxy = findMember(value, "proxy")) {
        const std::string proxyPointer = childPointer(pointer, "proxy");
        if (const auto name = readString(r.json, *proxy, proxyPointer)) {
            const auto it = std::find(kShellProxies.begin(), kShellProxies.end(), *name);
            if (it == kShellProxies.end()) {
                r.json.error(proxyPointer, "unknown proxy \"" + *name + "\"; expected one of " +
                                               quotedList(kShellProxies));
                return;
            }
            shell.proxy = ShellProxy(it - kShellProxies.begin());
        }
    }
    if (const Json* bound = findMember(value, "bound")) {
        if (auto half =
                readVec3(r.json, *bound, childPointer(pointer, "bound"), NumberRange::above(0.0)))
            shell.bound = *half;
    }
    const Json* mesh = findMember(value, "mesh");
    if (shell.proxy == ShellProxy::Mesh) {
        if (!mesh) {
            r.json.error(pointer, "a \"mesh\" proxy needs \"mesh\": the path of a glTF file, "
                                  "relative to the scene file");
            return;
        }
        const std::string meshPointer = childPointer(pointer, "mesh");
        if (const auto text = readString(r.json, *mesh, meshPointer)) {
            if (text->empty()) {
                r.json.error(meshPointer, "expected the path of a glTF file, got \"\"");
                return;
            }
            shell.meshFile = *text;
            shell.meshPath = resolveMeshPath(r.sceneFolder, *text);
        }
    } else if (mesh) {
        r.json.error(childPointer(pointer, "mesh"),
                     "\"mesh\" is read only with \"proxy\": \"mesh\"");
        return;
    }
    node.shell = shell;
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
    readModifiers(r, object, pointer, node);
    if (const Json* cut = findMember(object, "cut")) {
        if (cut->is_boolean()) {
            node.cut = cut->get<bool>();
        } else {
            r.json.error(childPointer(pointer, "cut"),
                         "expected true or false, got " + jsonTypeName(*cut));
        }
    }
    if (const Json* shell = findMember(object, "shell"))
        readShell(r, *shell, childPointer(pointer, "shell"), node);
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

} // namespace rmsc
