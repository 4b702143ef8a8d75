// Reading the "sdf" tree of a scene file (docs/scene-format.md, "`sdf`"): each node's shape and
// parameters or group and operation, its modifiers, profile, "cut" and "shell", checked against
// the catalogues (primitives, modifiers, operations, profiles) with every problem reported at its
// JSON pointer.
#include "sdf_json.hpp"

#include "core/limits.hpp"
#include "param_json.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"
#include "transform_json.hpp"

#include <algorithm>

namespace rmsc {
namespace {

constexpr int kMaxSdfGroupDepth = limits::kSdfGroupDepth;
constexpr int kMaxSdfNodes = limits::kSdfNodes;

const std::vector<std::string> kGroupKeys = {
    "name",       "op",    "smoothness", "blend",     "children", "position", "rotation",
    "quaternion", "scale", "material",   "modifiers", "cut",      "shell"};
const std::vector<std::string> kShapeCommonKeys = {"name",       "shape", "position", "rotation",
                                                   "quaternion", "scale", "material", "modifiers",
                                                   "cut",        "shell"};
const std::vector<std::string> kShellKeys = {"proxy", "bound", "mesh"};
const std::vector<std::string> kShellProxies = {"box", "sphere", "mesh"};

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
        std::string message = "unknown shape \"" + *name + "\"";
        if (const auto match = closeMatch(*name, shapes))
            message += "; did you mean \"" + *match + "\"?";
        r.json.error(shapePointer, message + " (known shapes: " +
                                       quotedList(sortedByDistance(*name, shapes)) + ")");
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
                            numberRange(smoothnessParam()));
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

} // namespace

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

} // namespace rmsc
