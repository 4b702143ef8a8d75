// Writing scenes as format version 1 JSON (sceneToJson): every section, materials referenced by
// name, shape parameters by their catalogue names, rotations as short Euler degrees where those
// read back exactly (else as exact quaternions) and numbers in the fewest digits that read back
// as the same float. Number arrays stay on one line.
#include "material_texture_json.hpp"
#include "scene/camera_spec.hpp"
#include "scene/scene_json.hpp"

#include "lighting_json.hpp"
#include "param_json.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"
#include "transform_json.hpp"

#include <algorithm>
#include <set>

namespace rmsc {
namespace {

// Material keys of the written file, one per Scene::materials entry. Scenes built in code may
// have empty or repeated names; those get "material_<index>" so every key is unique.
std::vector<std::string> materialKeys(const std::vector<Material>& materials) {
    std::set<std::string> used;
    for (const Material& m : materials)
        used.insert(m.name);
    std::vector<std::string> keys;
    std::set<std::string> taken;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        std::string key = materials[i].name;
        if (key.empty() || taken.count(key)) {
            int suffix = int(i);
            do {
                key = "material_" + std::to_string(suffix++);
            } while (used.count(key) || taken.count(key));
        }
        taken.insert(key);
        keys.push_back(key);
    }
    return keys;
}

// Writes "material" when `index` names a scene material (out-of-range indices are dropped).
void writeMaterialRef(int index, const std::vector<std::string>& keys, Json& object) {
    if (index >= 0 && std::size_t(index) < keys.size()) object["material"] = keys[index];
}

Json cameraToJson(const Camera& camera) {
    Json out = Json::object();
    out["position"] = vec3ToJson(camera.position);
    out["target"] = vec3ToJson(camera.target);
    out["up"] = vec3ToJson(camera.up);
    out["fov"] = floatToJson(camera.fovYDegrees);
    out["near"] = floatToJson(camera.nearPlane);
    out["far"] = floatToJson(camera.farPlane);
    // Written only for an orthographic camera: a perspective one's file stays as it was.
    if (camera.projection == CameraProjection::Orthographic) {
        out["projection"] = std::string(cameraProjectionName(camera.projection));
        out["ortho_height"] = floatToJson(camera.orthoHeight);
    }
    return out;
}

Json renderToJson(const RenderSettings& render) {
    Json out = Json::object();
    out["max_steps"] = render.maxSteps;
    out["max_distance"] = floatToJson(render.maxDistance);
    out["surface_epsilon"] = floatToJson(render.surfaceEpsilon);
    out["background"] = vec3ToJson(render.background);
    out["ambient"] = vec3ToJson(render.ambient);
    out["exposure"] = floatToJson(render.exposure);
    writeRenderLighting(render, out);
    return out;
}

// A modifier with the keys of its catalogue row.
Json modifierToJson(const SdfModifier& m) {
    const ModifierSpec& spec = modifierSpec(m.type);
    Json out = Json::object();
    out["type"] = spec.name;
    for (const ModifierParam& param : spec.params)
        std::visit([&](auto field) { writeParam(param.spec, m.*field, out); }, param.field);
    return out;
}

// "extrusion" / "revolution" and their profile, with the keys of their catalogue rows.
void writeProfileShape(const SdfProfile& profile, Json& out) {
    const ProfileSolidSpec& solid = profileSolidSpec(profile.solid);
    const ProfileSpec& spec = profileSpec(profile.type);
    out["shape"] = solid.name;
    Json p = Json::object();
    p["type"] = spec.name;
    for (const ProfileParam& param : spec.params)
        std::visit([&](auto field) { writeParam(param.spec, profile.*field, p); }, param.field);
    out["profile"] = std::move(p);
    std::visit([&](auto field) { writeParam(solid.param.spec, profile.*field, out); },
               solid.param.field);
}

Json sdfNodeToJson(const SdfNode& node, const std::vector<std::string>& materials) {
    Json out = Json::object();
    if (!node.name.empty()) out["name"] = node.name;
    if (node.isGroup) {
        out["op"] = operationSpec(node.op).name;
        if (takesSmoothness(node.op)) out["smoothness"] = floatToJson(node.smoothness);
        if (takesBlend(node.op) && node.blend != blendCatalogue().front().blend)
            out["blend"] = blendCatalogue()[std::size_t(node.blend)].name;
    } else if (node.profile) {
        writeProfileShape(*node.profile, out);
    } else {
        const PrimitiveSpec& spec = primitiveSpec(node.primitive);
        out["shape"] = spec.name;
        for (std::size_t i = 0; i < spec.params.size(); ++i) {
            const float* value = node.params.data() + paramOffset(spec, int(i));
            out[std::string(spec.params[i].name)] =
                spec.params[i].components == 1 ? floatToJson(*value)
                                               : vec3ToJson({value[0], value[1], value[2]});
        }
    }
    writeTransform(node.transform, out);
    writeMaterialRef(node.material, materials, out);
    if (node.cut) out["cut"] = true;
    if (node.shell) {
        const SdfShell& shell = *node.shell;
        static constexpr const char* kProxies[] = {"box", "sphere", "mesh"};
        Json s = Json::object();
        s["proxy"] = kProxies[std::size_t(shell.proxy)];
        if (shell.bound) s["bound"] = vec3ToJson(*shell.bound);
        if (shell.proxy == ShellProxy::Mesh) s["mesh"] = shell.meshFile;
        out["shell"] = std::move(s);
    }
    if (!node.modifiers.empty()) {
        Json modifiers = Json::array();
        for (const SdfModifier& m : node.modifiers)
            modifiers.push_back(modifierToJson(m));
        out["modifiers"] = std::move(modifiers);
    }
    if (node.isGroup) {
        Json children = Json::array();
        for (const SdfNode& child : node.children)
            children.push_back(sdfNodeToJson(child, materials));
        out["children"] = std::move(children);
    }
    return out;
}

Json sceneToJsonValue(const Scene& scene) {
    const std::vector<std::string> materialNames = materialKeys(scene.materials);
    Json root = Json::object();
    root["version"] = kSceneFormatVersion;
    root["camera"] = cameraToJson(scene.camera);
    root["render"] = renderToJson(scene.render);

    Json materials = Json::object();
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        materials[materialNames[i]] = {{"base_color", vec3ToJson(m.baseColor)},
                                       {"metallic", floatToJson(m.metallic)},
                                       {"roughness", floatToJson(m.roughness)},
                                       {"emissive", vec3ToJson(m.emissive)}};
        writeMaterialTextures(m, materials[materialNames[i]]);
    }
    root["materials"] = std::move(materials);

    Json lights = Json::array();
    for (const Light& light : scene.lights) {
        lights.push_back(lightToJson(light));
    }
    root["lights"] = std::move(lights);
    if (Json environment = environmentToJson(scene.environment); !environment.is_null())
        root["environment"] = std::move(environment);

    Json meshes = Json::array();
    for (const MeshInstance& mesh : scene.meshes) {
        Json out = Json::object();
        out["name"] = mesh.name;
        out["file"] = mesh.file.empty() ? mesh.path.generic_string() : mesh.file;
        writeTransform(mesh.transform, out);
        writeMaterialRef(mesh.materialOverride, materialNames, out);
        if (!mesh.animation.empty()) {
            out["animation"] = mesh.animation;
            out["time"] = mesh.time;
        }
        if (mesh.gltfScene >= 0) out["scene"] = mesh.gltfScene;
        meshes.push_back(std::move(out));
    }
    root["meshes"] = std::move(meshes);

    if (scene.sdf) root["sdf"] = sdfNodeToJson(*scene.sdf, materialNames);
    return root;
}

std::string scalarText(const Json& value) {
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// Like nlohmann's dump(2), but arrays of numbers stay on one line: "position": [0, 1.5, 5].
void writePretty(const Json& value, int indent, std::string& out) {
    const std::string inner(std::size_t(indent + 2), ' ');
    if (value.is_object() && !value.empty()) {
        out += "{\n";
        bool first = true;
        for (const auto& [key, member] : value.items()) {
            if (!first) out += ",\n";
            first = false;
            out += inner + scalarText(Json(key)) + ": ";
            writePretty(member, indent + 2, out);
        }
        out += "\n" + std::string(std::size_t(indent), ' ') + "}";
    } else if (value.is_array() && !value.empty()) {
        bool allNumbers = true;
        for (const Json& element : value)
            allNumbers = allNumbers && element.is_number();
        if (allNumbers) {
            out += "[";
            for (std::size_t i = 0; i < value.size(); ++i)
                out += (i ? ", " : "") + scalarText(value[i]);
            out += "]";
            return;
        }
        out += "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (i) out += ",\n";
            out += inner;
            writePretty(value[i], indent + 2, out);
        }
        out += "\n" + std::string(std::size_t(indent), ' ') + "]";
    } else {
        out += scalarText(value);
    }
}

} // namespace

std::string sceneToJson(const Scene& scene) {
    std::string out;
    writePretty(sceneToJsonValue(scene), 0, out);
    out += "\n";
    return out;
}

} // namespace rmsc
