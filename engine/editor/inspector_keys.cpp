// The keys the inspector edits (editor/inspector_keys.hpp). The hand-written rows name the
// controls in engine/viewer/inspector_*.cpp; parameters come from the catalogues the inspector
// draws its fields from.
#include "editor/inspector_keys.hpp"

#include "scene/light_spec.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"

#include <string_view>

namespace rmsc::editor {
namespace {

struct KeyControl {
    std::string_view key;
    std::string_view control;
};

// Every SDF node: engine/viewer/inspector_sdf_node.cpp and the widgets it calls.
constexpr KeyControl kNodeKeys[] = {
    {"name", "name"},
    {"material", "material"},
    {"modifiers", "add modifier / remove, one field per parameter"},
    {"cut", kCutControl},
    {"shell", "draw through a proxy mesh"},
    {"position", "position"},
    {"rotation", "rotation"},
    {"scale", "scale"},
    {"quaternion", "rotation (the same rotation; a save writes it as this exact quaternion)"},
};

constexpr KeyControl kGroupKeys[] = {
    {"op", "operation"},
    {"smoothness", "smoothness"},
    {"blend", kBlendControl},
};

constexpr KeyControl kShellKeys[] = {
    {"proxy", "proxy"},
    {"bound", "clip to a bound / bound"},
    {"mesh", "proxy (a glTF file)"},
};

// engine/viewer/inspector_light.cpp.
constexpr KeyControl kLightKeys[] = {
    {"type", "type"},
    {"name", "name"},
    {"color", "colour"},
    {"intensity", "intensity"},
    {"shadows", "casts shadows"},
    {"shadow_softness", "own shadow softness / shadow softness"},
};

// engine/viewer/inspector_material.cpp, inspector_textures.cpp.
constexpr KeyControl kMaterialKeys[] = {
    {"base_color", "base colour"},
    {"metallic", "metallic"},
    {"roughness", "roughness"},
    {"emissive", "emissive"},
    {"base_color_texture", "base colour texture: file"},
    {"normal_texture", "normal texture: file"},
    {"roughness_texture", "roughness texture: file"},
};

constexpr KeyControl kTextureKeys[] = {
    {"file", "file"},
    {"scale", "scale"},
    {"sharpness", "sharpness"},
};

// engine/viewer/inspector_render_settings.cpp.
constexpr KeyControl kRenderKeys[] = {
    {"max_steps", "max steps"},
    {"max_distance", "max distance"},
    {"surface_epsilon", "surface epsilon"},
    {"background", "background"},
    {"ambient", "ambient"},
    {"exposure", "exposure"},
    {"shadows", "shadows"},
    {"ao", "AO samples"},
    {"fxaa", "FXAA"},
};
constexpr KeyControl kShadowKeys[] = {
    {"enabled", "shadows"},
    {"steps", "shadow steps"},
    {"softness", "shadow softness"},
    {"min_distance", "shadow min distance"},
    {"max_distance", "shadow max distance"},
    {"map_size", "shadow map size"},
    {"pcf_radius", "shadow PCF radius"},
    {"normal_offset", "shadow normal offset"},
    {"slope_bias", "shadow slope bias"},
};
constexpr KeyControl kAoKeys[] = {
    {"samples", "AO samples"},
    {"distance", "AO distance"},
    {"strength", "AO strength"},
};

// engine/viewer/inspector_view.cpp: the scene camera.
constexpr KeyControl kCameraKeys[] = {
    {"position", "Camera: position (and Save camera to scene)"},
    {"target", "Camera: target (and Save camera to scene)"},
    {"up", "Camera: up (and Save camera to scene)"},
    {"fov", "fov"},
    {"near", "near"},
    {"far", "far"},
    {"projection", "projection"},
    {"ortho_height", "ortho height (shown for an orthographic camera)"},
};

// engine/viewer/inspector_mesh.cpp.
constexpr KeyControl kMeshKeys[] = {
    {"name", "name"},
    {"file", "file (applied when it loads)"},
    {"material", "material"},
    {"animation", "animation"},
    {"time", "time (drag to scrub the animation, or play it)"},
    {"scene", "glTF scene"},
    {"position", "position"},
    {"rotation", "rotation"},
    {"scale", "scale"},
    {"quaternion", "rotation (the same rotation; a save writes it as this exact quaternion)"},
};

// engine/viewer/inspector_environment.cpp.
constexpr KeyControl kEnvironmentKeys[] = {
    {"sky", "Environment: sky"},
    {"intensity", "Environment: intensity"},
    {"fog", "Environment: fog"},
};
constexpr KeyControl kSkyConstantKeys[] = {
    {"type", "Environment: sky"},
    {"color", "Environment: colour"},
};
constexpr KeyControl kSkyGradientKeys[] = {
    {"type", "Environment: sky"},
    {"zenith", "Environment: zenith"},
    {"horizon", "Environment: horizon"},
    {"ground", "Environment: ground"},
};
constexpr KeyControl kSkyImageKeys[] = {
    {"type", "Environment: sky"},
    {"file", "Environment: file (applied when it loads)"},
    {"rotation", "Environment: rotation"},
};
constexpr KeyControl kFogKeys[] = {
    {"color", "Environment: fog colour"},
    {"density", "Environment: fog / density"},
};

// The scene's top level: each key is a part of the editor of its own.
constexpr KeyControl kSceneKeysElsewhere[] = {
    {"version", "the format version: every save writes the version it reads"},
    {"camera", "the Render tab's Camera section"},
    {"render", "the Render tab's render settings"},
    {"materials", "an object's material: choose or create one (the inspector edits it there)"},
    {"lights", "+ Light and the Add menu; the Object tab edits the selected light"},
    {"meshes", "the Add menu's glTF mesh; the Object tab edits the selected mesh"},
    {"environment", "the Render tab's Environment section"},
    {"sdf", "the Scene panel (+ Shape, + Group); the Object tab edits the selected node"},
};

void add(std::vector<InspectorKey>& keys, const std::string& object,
         std::span<const KeyControl> rows) {
    for (const KeyControl& row : rows)
        keys.push_back({object, std::string(row.key), std::string(row.control)});
}

// The SDF node objects of the schema: the group, each primitive's shape and each profile solid.
std::vector<std::string> nodeObjects() {
    std::vector<std::string> objects = {"group"};
    for (const PrimitiveSpec& spec : primitiveCatalogue())
        objects.push_back("shape_" + std::string(spec.name));
    for (const ProfileSolidSpec& solid : profileSolidCatalogue())
        objects.push_back("shape_" + std::string(solid.name));
    return objects;
}

} // namespace

std::vector<InspectorKey> inspectorKeys() {
    std::vector<InspectorKey> keys;
    for (const std::string& object : nodeObjects())
        add(keys, object, kNodeKeys);
    add(keys, "group", kGroupKeys);
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        const std::string object = "shape_" + std::string(spec.name);
        keys.push_back({object, "shape", "shape"});
        for (const ParamSpec& p : spec.params)
            keys.push_back({object, std::string(p.name), std::string(p.name)});
    }
    for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
        const std::string object = "shape_" + std::string(solid.name);
        keys.push_back({object, "shape", "shape"});
        keys.push_back({object, "profile", "profile"});
        keys.push_back(
            {object, std::string(solid.param.spec.key), std::string(solid.param.spec.key)});
    }
    for (const ProfileSpec& spec : profileCatalogue()) {
        const std::string object = "profile_" + std::string(spec.name);
        keys.push_back({object, "type", "profile"});
        for (const ProfileParam& p : spec.params)
            keys.push_back({object, std::string(p.spec.key), std::string(p.spec.key)});
    }
    for (const ModifierSpec& spec : modifierCatalogue()) {
        const std::string object = "modifier_" + std::string(spec.name);
        keys.push_back({object, "type", "add modifier"});
        for (const ModifierParam& p : spec.params)
            keys.push_back({object, std::string(p.spec.key), std::string(p.spec.key)});
    }
    add(keys, "shell", kShellKeys);
    for (LightType type : kLightTypes) {
        const std::string object = "light_" + std::string(lightTypeName(type));
        add(keys, object, kLightKeys);
        if (hasPosition(type)) keys.push_back({object, "position", "position"});
        if (hasDirection(type)) keys.push_back({object, "direction", "azimuth / elevation"});
        if (hasRange(type)) keys.push_back({object, "range", "limited range / range"});
        if (hasCone(type)) {
            keys.push_back({object, "inner_angle", "inner angle"});
            keys.push_back({object, "outer_angle", "outer angle"});
        }
    }
    add(keys, "material", kMaterialKeys);
    add(keys, "texture", kTextureKeys);
    add(keys, "normal_texture", kTextureKeys);
    keys.push_back({"normal_texture", "strength", "strength"});
    add(keys, "render", kRenderKeys);
    add(keys, "shadows", kShadowKeys);
    add(keys, "ao", kAoKeys);
    add(keys, "camera", kCameraKeys);
    add(keys, "mesh", kMeshKeys);
    add(keys, "environment", kEnvironmentKeys);
    add(keys, "sky_constant", kSkyConstantKeys);
    add(keys, "sky_gradient", kSkyGradientKeys);
    add(keys, "sky_image", kSkyImageKeys);
    add(keys, "fog", kFogKeys);
    return keys;
}

std::vector<InspectorKey> keysNotInInspector() {
    std::vector<InspectorKey> keys;
    keys.push_back({"group", "children",
                    "the Scene panel edits the hierarchy (+ Shape, + Group, drag and drop, "
                    "Ctrl+D, Delete)"});
    add(keys, kSceneObject, kSceneKeysElsewhere);
    return keys;
}

} // namespace rmsc::editor
