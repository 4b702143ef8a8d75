// JSON-level checks of a glTF document (see gltf_json_checks.hpp).
#include "gltf_json_checks.hpp"

#include "scene/gltf_extensions.hpp"

#include "gltf_files.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

namespace rmsc::gltf {

namespace {

using nlohmann::json;

// Properties whose values (or array elements) are glTF indices or sizes: non-negative integers
// that must fit tinygltf's int fields without being truncated.
constexpr std::array<std::string_view, 21> kIndexKeys = {
    "scene",  "mesh",          "skin",    "camera",   "material",   "indices",    "bufferView",
    "buffer", "source",        "sampler", "index",    "byteOffset", "byteLength", "byteStride",
    "count",  "componentType", "mode",    "texCoord", "node",       "nodes",      "children"};

bool isIndexKey(std::string_view key) {
    for (std::string_view k : kIndexKeys)
        if (k == key) return true;
    return false;
}

std::string pointerToken(std::string_view key) {
    std::string out;
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string shortDump(const json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 40) + "...";
    return text;
}

void checkIndexValue(const json& value, const std::string& pointer, Reporter& report) {
    constexpr std::int64_t kMax = std::numeric_limits<std::int32_t>::max();
    if (value.is_number_unsigned() && value.get<std::uint64_t>() <= std::uint64_t(kMax)) return;
    if (value.is_number_integer() && !value.is_number_unsigned()) {
        const std::int64_t v = value.get<std::int64_t>();
        if (v >= 0 && v <= kMax) return;
    }
    report.error(pointer, "expected an integer from 0 to " + std::to_string(kMax) + ", got " +
                              shortDump(value));
}

void walk(const json& value, const std::string& pointer, Reporter& report) {
    if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            walk(value[i], pointer + "/" + std::to_string(i), report);
        return;
    }
    if (!value.is_object()) return;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string& key = it.key();
        if (key == "extras" || key == "extensions") continue; // free-form data
        const std::string child = pointer + "/" + pointerToken(key);
        const json& v = it.value();
        if (key == "attributes" && v.is_object()) {
            for (auto a = v.begin(); a != v.end(); ++a)
                checkIndexValue(a.value(), child + "/" + pointerToken(a.key()), report);
        } else if (isIndexKey(key)) {
            if (v.is_array()) {
                for (std::size_t i = 0; i < v.size(); ++i)
                    if (!v[i].is_object())
                        checkIndexValue(v[i], child + "/" + std::to_string(i), report);
            } else if (!v.is_object()) {
                checkIndexValue(v, child, report);
            }
        }
        walk(v, child, report);
    }
}

void checkBuffers(const json& root, const JsonCheckInput& input, Reporter& report) {
    const auto it = root.find("buffers");
    if (it == root.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size(); ++i) {
        const json& buffer = (*it)[i];
        const std::string pointer = "/buffers/" + std::to_string(i);
        if (!buffer.is_object()) continue; // reported by tinygltf
        const auto lengthIt = buffer.find("byteLength");
        if (lengthIt == buffer.end() || !lengthIt->is_number_unsigned()) {
            report.error(pointer + "/byteLength", "expected the buffer's length in bytes");
            continue;
        }
        const std::uint64_t byteLength = lengthIt->get<std::uint64_t>();
        const auto uriIt = buffer.find("uri");
        if (uriIt == buffer.end()) {
            if (!input.isGlb) {
                report.error(pointer, "buffer has no \"uri\"; only a binary glTF (.glb) may "
                                      "leave it out for its BIN chunk");
            } else if (i != 0) {
                report.error(pointer, "only buffer 0 may refer to the GLB BIN chunk");
            } else if (!input.hasBinChunk) {
                report.error(pointer, "buffer refers to the GLB BIN chunk, but the file has none");
            } else if (byteLength > input.binSize) {
                report.error(pointer + "/byteLength",
                             "buffer is " + std::to_string(byteLength) +
                                 " bytes but the GLB BIN chunk holds only " +
                                 std::to_string(input.binSize));
            }
            continue;
        }
        if (!uriIt->is_string()) {
            report.error(pointer + "/uri", "expected a string");
            continue;
        }
        const std::string& uri = uriIt->get_ref<const std::string&>();
        std::string why;
        if (isDataUri(uri)) {
            const auto info = inspectDataUri(uri, why);
            if (!info) {
                report.error(pointer + "/uri", why);
            } else if (info->mediaType != "application/octet-stream" &&
                       info->mediaType != "application/gltf-buffer") {
                report.error(pointer + "/uri", "data URI media type \"" + info->mediaType +
                                                   "\", expected application/octet-stream or "
                                                   "application/gltf-buffer");
            } else if (info->decodedSize != byteLength) {
                report.error(pointer, "data URI holds " + std::to_string(info->decodedSize) +
                                          " bytes but byteLength is " + std::to_string(byteLength));
            }
            continue;
        }
        const auto decoded = percentDecode(uri);
        if (!decoded)
            report.error(pointer + "/uri", "malformed percent escape in URI");
        else if (!resolveInFolder(*decoded, why))
            report.error(pointer + "/uri", why);
    }
}

void checkImages(const json& root, Reporter& report) {
    const auto it = root.find("images");
    if (it == root.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size(); ++i) {
        const json& image = (*it)[i];
        const std::string pointer = "/images/" + std::to_string(i) + "/uri";
        if (!image.is_object()) continue;
        const auto uriIt = image.find("uri");
        if (uriIt == image.end()) continue;
        if (!uriIt->is_string()) {
            report.error(pointer, "expected a string");
            continue;
        }
        const std::string& uri = uriIt->get_ref<const std::string&>();
        std::string why;
        if (isDataUri(uri)) {
            const auto info = inspectDataUri(uri, why);
            if (!info)
                report.error(pointer, why);
            else if (info->mediaType != "image/png" && info->mediaType != "image/jpeg")
                report.error(pointer, "data URI media type \"" + info->mediaType +
                                          "\", expected image/png or image/jpeg");
            continue;
        }
        const auto decoded = percentDecode(uri);
        if (!decoded)
            report.error(pointer, "malformed percent escape in URI");
        else if (!resolveInFolder(*decoded, why))
            report.error(pointer, why);
    }
}

// KHR_lights_punctual's lights, which tinygltf refuses without a pointer (a light without a
// "type", a spot light without "spot") and whose optional values of the wrong type it drops
// silently. Values are checked further when a node uses the light (gltf_lights.cpp).
void checkLights(const json& root, Reporter& report) {
    const auto extensions = root.find("extensions");
    if (extensions == root.end() || !extensions->is_object()) return;
    const auto punctual = extensions->find("KHR_lights_punctual");
    if (punctual == extensions->end()) return;
    const std::string extensionPointer = "/extensions/KHR_lights_punctual";
    if (!punctual->is_object()) {
        report.error(extensionPointer, "expected an object with a \"lights\" array");
        return;
    }
    const auto lights = punctual->find("lights");
    if (lights == punctual->end()) return;
    if (!lights->is_array()) {
        report.error(extensionPointer + "/lights", "expected an array of lights");
        return;
    }
    const auto expectNumber = [&](const json& light, const char* key, const std::string& p) {
        const auto it = light.find(key);
        if (it != light.end() && !it->is_number())
            report.error(p + "/" + key, "expected a number, got " + shortDump(*it));
    };
    for (std::size_t i = 0; i < lights->size(); ++i) {
        const json& light = (*lights)[i];
        const std::string pointer = extensionPointer + "/lights/" + std::to_string(i);
        if (!light.is_object()) {
            report.error(pointer, "expected a light object with a \"type\"");
            continue;
        }
        const auto type = light.find("type");
        if (type == light.end() || !type->is_string() ||
            (*type != "directional" && *type != "point" && *type != "spot")) {
            report.error(pointer + "/type",
                         "expected \"directional\", \"point\" or \"spot\", got " +
                             (type == light.end() ? std::string("nothing") : shortDump(*type)));
        } else if (*type == "spot") {
            const auto spot = light.find("spot");
            if (spot == light.end() || !spot->is_object()) {
                report.error(pointer + "/spot",
                             "expected an object with the spot light's cone angles");
            } else {
                expectNumber(*spot, "innerConeAngle", pointer + "/spot");
                expectNumber(*spot, "outerConeAngle", pointer + "/spot");
            }
        }
        const auto color = light.find("color");
        if (color != light.end() && !(color->is_array() && color->size() == 3 &&
                                      std::all_of(color->begin(), color->end(),
                                                  [](const json& c) { return c.is_number(); })))
            report.error(pointer + "/color", "expected 3 numbers, got " + shortDump(*color));
        expectNumber(light, "intensity", pointer);
        expectNumber(light, "range", pointer);
    }
}

// --- references between top-level arrays -------------------------------------------------

std::size_t arraySize(const json& root, const char* key) {
    const auto it = root.find(key);
    return it != root.end() && it->is_array() ? it->size() : 0;
}

// Reports `value` (at `pointer`) when it is an index outside [0, count) of `target`. Values that
// are not integers were already reported by walk().
void checkIndexInRange(const json& value, std::size_t count, const char* target,
                       const std::string& pointer, Reporter& report) {
    if (!value.is_number_unsigned()) return;
    const std::uint64_t index = value.get<std::uint64_t>();
    if (index < count) return;
    report.error(pointer, "refers to " + std::string(target) + " " + std::to_string(index) +
                              ", but the file has " + std::to_string(count) + " " + target);
}

void checkRef(const json& parent, const char* key, std::size_t count, const char* target,
              const std::string& pointer, Reporter& report) {
    if (!parent.is_object()) return;
    const auto it = parent.find(key);
    if (it != parent.end()) checkIndexInRange(*it, count, target, pointer + "/" + key, report);
}

void checkRefArray(const json& parent, const char* key, std::size_t count, const char* target,
                   const std::string& pointer, Reporter& report) {
    if (!parent.is_object()) return;
    const auto it = parent.find(key);
    if (it == parent.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size(); ++i)
        checkIndexInRange((*it)[i], count, target, pointer + "/" + key + "/" + std::to_string(i),
                          report);
}

// Calls f(element, pointer) for each object in root[key].
template <typename F> void forEachObject(const json& root, const char* key, F&& f) {
    const auto it = root.find(key);
    if (it == root.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size(); ++i)
        if ((*it)[i].is_object()) f((*it)[i], "/" + std::string(key) + "/" + std::to_string(i));
}

const json* member(const json& parent, const char* key) {
    const auto it = parent.find(key);
    return it != parent.end() && it->is_object() ? &*it : nullptr;
}

void checkReferences(const json& root, Reporter& report) {
    const std::size_t scenes = arraySize(root, "scenes"), nodes = arraySize(root, "nodes"),
                      meshes = arraySize(root, "meshes"), accessors = arraySize(root, "accessors"),
                      views = arraySize(root, "bufferViews"), buffers = arraySize(root, "buffers"),
                      materials = arraySize(root, "materials"),
                      textures = arraySize(root, "textures"), images = arraySize(root, "images"),
                      samplers = arraySize(root, "samplers"), cameras = arraySize(root, "cameras"),
                      skins = arraySize(root, "skins");
    checkRef(root, "scene", scenes, "scenes", "", report);
    forEachObject(root, "scenes", [&](const json& scene, const std::string& p) {
        checkRefArray(scene, "nodes", nodes, "nodes", p, report);
    });
    forEachObject(root, "nodes", [&](const json& node, const std::string& p) {
        checkRefArray(node, "children", nodes, "nodes", p, report);
        checkRef(node, "mesh", meshes, "meshes", p, report);
        checkRef(node, "camera", cameras, "cameras", p, report);
        checkRef(node, "skin", skins, "skins", p, report);
    });
    forEachObject(root, "meshes", [&](const json& mesh, const std::string& meshPointer) {
        forEachObject(mesh, "primitives", [&](const json& primitive, const std::string& p) {
            const std::string pointer = meshPointer + p;
            if (const json* attributes = member(primitive, "attributes"))
                for (auto a = attributes->begin(); a != attributes->end(); ++a)
                    checkIndexInRange(a.value(), accessors, "accessors",
                                      pointer + "/attributes/" + pointerToken(a.key()), report);
            checkRef(primitive, "indices", accessors, "accessors", pointer, report);
            checkRef(primitive, "material", materials, "materials", pointer, report);
            forEachObject(primitive, "targets", [&](const json& target, const std::string& t) {
                for (auto a = target.begin(); a != target.end(); ++a)
                    checkIndexInRange(a.value(), accessors, "accessors",
                                      pointer + t + "/" + pointerToken(a.key()), report);
            });
        });
    });
    forEachObject(root, "materials", [&](const json& material, const std::string& p) {
        if (const json* pbr = member(material, "pbrMetallicRoughness")) {
            for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
                if (const json* info = member(*pbr, key))
                    checkRef(*info, "index", textures, "textures",
                             p + "/pbrMetallicRoughness/" + key, report);
        }
        for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
            if (const json* info = member(material, key))
                checkRef(*info, "index", textures, "textures", p + "/" + key, report);
    });
    forEachObject(root, "textures", [&](const json& texture, const std::string& p) {
        checkRef(texture, "source", images, "images", p, report);
        checkRef(texture, "sampler", samplers, "samplers", p, report);
    });
    forEachObject(root, "images", [&](const json& image, const std::string& p) {
        checkRef(image, "bufferView", views, "bufferViews", p, report);
    });
    forEachObject(root, "accessors", [&](const json& accessor, const std::string& p) {
        checkRef(accessor, "bufferView", views, "bufferViews", p, report);
        if (const json* sparse = member(accessor, "sparse")) {
            for (const char* key : {"indices", "values"})
                if (const json* part = member(*sparse, key))
                    checkRef(*part, "bufferView", views, "bufferViews", p + "/sparse/" + key,
                             report);
        }
    });
    forEachObject(root, "bufferViews", [&](const json& view, const std::string& p) {
        checkRef(view, "buffer", buffers, "buffers", p, report);
    });
    forEachObject(root, "skins", [&](const json& skin, const std::string& p) {
        checkRefArray(skin, "joints", nodes, "nodes", p, report);
        checkRef(skin, "skeleton", nodes, "nodes", p, report);
        checkRef(skin, "inverseBindMatrices", accessors, "accessors", p, report);
    });
    forEachObject(root, "animations", [&](const json& animation, const std::string& a) {
        const std::size_t animationSamplers = arraySize(animation, "samplers");
        forEachObject(animation, "channels", [&](const json& channel, const std::string& p) {
            checkRef(channel, "sampler", animationSamplers, "samplers", a + p, report);
            if (const json* target = member(channel, "target"))
                checkRef(*target, "node", nodes, "nodes", a + p + "/target", report);
        });
        forEachObject(animation, "samplers", [&](const json& sampler, const std::string& p) {
            checkRef(sampler, "input", accessors, "accessors", a + p, report);
            checkRef(sampler, "output", accessors, "accessors", a + p, report);
        });
    });
}

// Every "extensions" object below `value`: the first pointer at which each name appears.
void collectExtensionUses(const json& value, const std::string& pointer,
                          std::map<std::string, std::string>& firstUse) {
    if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            collectExtensionUses(value[i], pointer + "/" + std::to_string(i), firstUse);
        return;
    }
    if (!value.is_object()) return;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string child = pointer + "/" + pointerToken(it.key());
        if (it.key() == "extras") continue;
        if (it.key() == "extensions" && it.value().is_object()) {
            for (auto e = it.value().begin(); e != it.value().end(); ++e)
                firstUse.try_emplace(e.key(), child + "/" + pointerToken(e.key()));
        }
        collectExtensionUses(it.value(), child, firstUse);
    }
}

// extensionsRequired: every name rmsc lacks is an error naming it. extensionsUsed and the
// "extensions" objects of the file: every unsupported name gets one warning, at its entry in
// extensionsUsed or, when the file does not declare it, where it is first used.
void checkExtensions(const json& root, Reporter& report) {
    std::set<std::string> refused;
    const auto required = root.find("extensionsRequired");
    if (required != root.end() && required->is_array()) {
        for (std::size_t i = 0; i < required->size(); ++i) {
            const json& name = (*required)[i];
            const std::string pointer = "/extensionsRequired/" + std::to_string(i);
            if (!name.is_string()) {
                report.error(pointer, "expected an extension name, got " + shortDump(name));
            } else if (!gltfExtensionSupported(name.get_ref<const std::string&>())) {
                report.error(pointer, "the file requires extension " +
                                          name.get_ref<const std::string&>() +
                                          ", which rmsc does not support");
                refused.insert(name.get<std::string>());
            }
        }
    }
    std::map<std::string, std::string> firstUse; // name -> pointer, in name order
    std::vector<std::pair<std::string, std::string>> declared;
    const auto used = root.find("extensionsUsed");
    if (used != root.end() && used->is_array()) {
        for (std::size_t i = 0; i < used->size(); ++i)
            if ((*used)[i].is_string())
                declared.emplace_back((*used)[i].get<std::string>(),
                                      "/extensionsUsed/" + std::to_string(i));
    }
    collectExtensionUses(root, "", firstUse);
    std::set<std::string> warned = refused;
    const auto warn = [&](const std::string& name, const std::string& pointer) {
        if (gltfExtensionSupported(name) || !warned.insert(name).second) return;
        report.warning(pointer, "extension " + name +
                                    " is not supported; what it adds is "
                                    "ignored");
    };
    for (const auto& [name, pointer] : declared)
        warn(name, pointer);
    for (const auto& [name, pointer] : firstUse)
        warn(name, pointer);
}

} // namespace

bool checkGltfJson(const json& root, const JsonCheckInput& input, Reporter& report) {
    const int errorsBefore = report.errors;
    if (!root.is_object()) {
        report.error("", "expected a JSON object at the top level of a glTF file");
        return false;
    }
    const auto asset = root.find("asset");
    const json* version = nullptr;
    if (asset != root.end() && asset->is_object()) {
        const auto v = asset->find("version");
        if (v != asset->end() && v->is_string()) version = &*v;
    }
    if (version == nullptr)
        report.error("/asset/version", "expected the glTF version string, e.g. \"2.0\"");
    else if (version->get_ref<const std::string&>().rfind("2.", 0) != 0)
        report.error("/asset/version",
                     "glTF version " + version->get<std::string>() + ", expected 2.x");
    checkExtensions(root, report);
    walk(root, "", report);
    checkReferences(root, report);
    checkBuffers(root, input, report);
    checkImages(root, report);
    checkLights(root, report);
    return report.errors == errorsBefore;
}

} // namespace rmsc::gltf
