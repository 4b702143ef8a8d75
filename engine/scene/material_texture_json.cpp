// Material texture fields of the scene format (see material_texture_json.hpp).
#include "material_texture_json.hpp"

#include "param_json.hpp"
#include "scene/material_spec.hpp"

namespace rmsc {
namespace {

struct TextureField {
    const char* key;
    MaterialTexture Material::*member;
    bool hasStrength; // normal maps: "strength" scales the map's x and y
};

constexpr TextureField kTextureFields[] = {
    {"base_color_texture", &Material::baseColorTexture, false},
    {"normal_texture", &Material::normalTexture, true},
    {"roughness_texture", &Material::roughnessTexture, false},
};

const std::vector<std::string> kTextureKeys = {"file", "scale", "sharpness"};
const std::vector<std::string> kNormalTextureKeys = {"file", "scale", "sharpness", "strength"};

void readTexture(const JsonReader& reader, const Json& value, const std::string& pointer,
                 const std::filesystem::path& sceneFolder, bool hasStrength,
                 MaterialTexture& texture) {
    // A bare string is shorthand for {"file": ...}.
    if (value.is_string()) {
        texture.file = value.get<std::string>();
    } else {
        if (!value.is_object()) {
            reader.error(pointer, "expected a texture object {\"file\": \"textures/a.png\", ...} "
                                  "or a file name, got " +
                                      jsonTypeName(value));
            return;
        }
        warnUnknownKeys(reader, value, pointer, hasStrength ? kNormalTextureKeys : kTextureKeys);
        const Json* file = findMember(value, "file");
        if (!file) {
            reader.error(pointer, "expected a \"file\" naming a PNG or JPEG image");
            return;
        }
        const auto name = readString(reader, *file, childPointer(pointer, "file"));
        if (!name) return;
        texture.file = *name;
        readNumberField(reader, value, pointer, "scale", &texture.scale,
                        numberRange(kTextureScaleRange));
        readNumberField(reader, value, pointer, "sharpness", &texture.sharpness,
                        numberRange(kTextureSharpnessRange));
        if (hasStrength)
            readNumberField(reader, value, pointer, "strength", &texture.strength,
                            numberRange(kNormalStrengthRange));
    }
    const std::string filePointer = value.is_string() ? pointer : childPointer(pointer, "file");
    texture.pointer = filePointer;
    if (texture.file.empty()) {
        reader.error(filePointer, "expected a file name, got an empty string");
        return;
    }
    const std::filesystem::path path(texture.file);
    texture.path = (path.is_absolute() ? path : sceneFolder / path).lexically_normal();
}

} // namespace

const std::vector<std::string>& materialTextureKeys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> out;
        for (const TextureField& field : kTextureFields)
            out.push_back(field.key);
        return out;
    }();
    return keys;
}

const std::vector<MaterialTexture Material::*>& materialTextureMembers() {
    static const std::vector<MaterialTexture Material::*> members = [] {
        std::vector<MaterialTexture Material::*> out;
        for (const TextureField& field : kTextureFields)
            out.push_back(field.member);
        return out;
    }();
    return members;
}

void readMaterialTextures(const JsonReader& reader, const Json& object, const std::string& pointer,
                          const std::filesystem::path& sceneFolder, Material& material) {
    for (const TextureField& field : kTextureFields) {
        const Json* value = findMember(object, field.key);
        if (!value) continue;
        MaterialTexture texture;
        readTexture(reader, *value, childPointer(pointer, field.key), sceneFolder,
                    field.hasStrength, texture);
        material.*field.member = std::move(texture);
    }
}

void writeMaterialTextures(const Material& material, Json& object) {
    for (const TextureField& field : kTextureFields) {
        const MaterialTexture& texture = material.*field.member;
        if (!texture.present()) continue;
        Json out = Json::object();
        out["file"] = texture.file;
        out["scale"] = texture.scale;
        out["sharpness"] = texture.sharpness;
        if (field.hasStrength) out["strength"] = texture.strength;
        object[field.key] = std::move(out);
    }
}

} // namespace rmsc
