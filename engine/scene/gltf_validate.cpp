// Structural checks of a parsed glTF model (see gltf_validate.hpp).
#include "gltf_validate.hpp"

#include "gltf_accessors.hpp"

#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

namespace rmsc::gltf {

namespace {

bool allFinite(const std::vector<double>& values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

void checkBufferViews(const tinygltf::Model& model, Reporter& report) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const tinygltf::BufferView& view = model.bufferViews[i];
        const std::string pointer = "/bufferViews/" + std::to_string(i);
        if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size()) {
            report.error(pointer + "/buffer", "refers to a buffer that does not exist");
            continue;
        }
        const std::uint64_t size = model.buffers[std::size_t(view.buffer)].data.size();
        std::uint64_t end = 0;
        if (view.byteLength == 0) {
            report.error(pointer + "/byteLength", "expected at least 1 byte");
        } else if (__builtin_add_overflow(std::uint64_t(view.byteOffset),
                                          std::uint64_t(view.byteLength), &end) ||
                   end > size) {
            report.error(pointer, "bytes " + std::to_string(view.byteOffset) + " + " +
                                      std::to_string(view.byteLength) + " lie beyond the end of " +
                                      "/buffers/" + std::to_string(view.buffer) + " (" +
                                      std::to_string(size) + " bytes)");
        }
    }
}

void checkNodes(const tinygltf::Model& model, Reporter& report) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& node = model.nodes[i];
        const std::string pointer = "/nodes/" + std::to_string(i);
        const auto checkArray = [&](const std::vector<double>& values, std::size_t expected,
                                    const char* name) {
            if (values.empty()) return;
            if (values.size() != expected)
                report.error(pointer + "/" + name, "expected " + std::to_string(expected) +
                                                       " numbers, got " +
                                                       std::to_string(values.size()));
            else if (!allFinite(values))
                report.error(pointer + "/" + name, "expected finite numbers");
        };
        checkArray(node.matrix, 16, "matrix");
        checkArray(node.translation, 3, "translation");
        checkArray(node.rotation, 4, "rotation");
        checkArray(node.scale, 3, "scale");
        if (!node.matrix.empty() &&
            !(node.translation.empty() && node.rotation.empty() && node.scale.empty()))
            report.error(pointer, "has both a matrix and translation/rotation/scale, "
                                  "expected one or the other");
    }
}

// One parent per node, no cycles, depth at most kMaxNodeDepth.
void checkHierarchy(const tinygltf::Model& model, Reporter& report) {
    const std::size_t count = model.nodes.size();
    std::vector<int> parent(count, -1);
    bool ok = true;
    for (std::size_t p = 0; p < count; ++p) {
        for (int child : model.nodes[p].children) {
            if (child < 0 || std::size_t(child) >= count) continue; // reported on the JSON
            const std::string pointer = "/nodes/" + std::to_string(child);
            if (std::size_t(child) == p) {
                report.error(pointer, "node is its own child (a cycle)");
                ok = false;
            } else if (parent[std::size_t(child)] >= 0) {
                report.error(pointer, "node has more than one parent (/nodes/" +
                                          std::to_string(parent[std::size_t(child)]) +
                                          " and /nodes/" + std::to_string(p) +
                                          "), expected a tree");
                ok = false;
            } else {
                parent[std::size_t(child)] = int(p);
            }
        }
    }
    if (!ok) return;
    // With one parent each, walking up from any node either reaches a root or loops. depth[n]
    // is the number of nodes from the root down to n, once known (0 = not yet).
    std::vector<int> depth(count, 0);
    std::vector<char> onPath(count, 0);
    for (std::size_t start = 0; start < count; ++start) {
        std::vector<int> path;
        int n = int(start);
        while (n >= 0 && depth[std::size_t(n)] == 0) {
            if (onPath[std::size_t(n)]) {
                report.error("/nodes/" + std::to_string(n),
                             "node hierarchy has a cycle through this node, expected a tree");
                return;
            }
            onPath[std::size_t(n)] = 1;
            path.push_back(n);
            n = parent[std::size_t(n)];
        }
        int d = n >= 0 ? depth[std::size_t(n)] : 0;
        for (auto it = path.rbegin(); it != path.rend(); ++it) {
            depth[std::size_t(*it)] = ++d;
            onPath[std::size_t(*it)] = 0;
        }
        if (d > kMaxNodeDepth) {
            report.error("/nodes/" + std::to_string(start),
                         "node is nested " + std::to_string(d) + " levels deep, more than " +
                             "the limit of " + std::to_string(kMaxNodeDepth));
            return;
        }
    }
    // Each root once per scene: one pass counts how often each node is listed, a second
    // reports each node listed more than once, once, at its second entry.
    std::vector<std::size_t> firstEntry(count), entries(count, 0);
    for (std::size_t s = 0; s < model.scenes.size(); ++s) {
        const std::vector<int>& roots = model.scenes[s].nodes;
        const std::string scenePointer = "/scenes/" + std::to_string(s) + "/nodes/";
        for (std::size_t i = 0; i < roots.size(); ++i) {
            const int n = roots[i];
            if (n < 0 || std::size_t(n) >= count) continue;
            if (entries[std::size_t(n)]++ > 0) continue;
            firstEntry[std::size_t(n)] = i;
            if (parent[std::size_t(n)] >= 0)
                report.error(scenePointer + std::to_string(i),
                             "scene root /nodes/" + std::to_string(n) + " is a child of /nodes/" +
                                 std::to_string(parent[std::size_t(n)]) + ", expected a root node");
        }
        for (std::size_t i = 0; i < roots.size(); ++i) {
            const int n = roots[i];
            if (n < 0 || std::size_t(n) >= count) continue;
            std::size_t& listed = entries[std::size_t(n)];
            if (listed > 1 && i == firstEntry[std::size_t(n)]) continue; // report at the second
            if (listed > 1)
                report.error(scenePointer + std::to_string(i),
                             "/nodes/" + std::to_string(n) + " is listed " +
                                 std::to_string(listed) + " times in the scene (first at " +
                                 scenePointer + std::to_string(firstEntry[std::size_t(n)]) +
                                 "), expected each root once");
            listed = 0; // reported, or listed once: cleared for the next scene
        }
    }
}

// KHR_texture_transform of one textureInfo at `pointer`: offset and scale two finite
// numbers, rotation a finite number, texCoord a TEXCOORD set index.
void checkTextureTransform(const tinygltf::ExtensionMap& extensions, const std::string& pointer,
                           Reporter& report) {
    const auto ext = extensions.find("KHR_texture_transform");
    if (ext == extensions.end()) return;
    const std::string p = pointer + "/extensions/KHR_texture_transform";
    const tinygltf::Value& v = ext->second;
    if (!v.IsObject()) {
        report.error(p, "expected an object");
        return;
    }
    const auto finite = [](const tinygltf::Value& x) {
        return x.IsNumber() && std::isfinite(x.GetNumberAsDouble());
    };
    for (const char* key : {"offset", "scale"}) {
        if (!v.Has(key)) continue;
        const tinygltf::Value& a = v.Get(key);
        if (!a.IsArray() || a.ArrayLen() != 2 || !finite(a.Get(0)) || !finite(a.Get(1)))
            report.error(p + "/" + key, "expected 2 finite numbers");
    }
    if (v.Has("rotation") && !finite(v.Get("rotation")))
        report.error(p + "/rotation", "expected a finite number (radians)");
    if (v.Has("texCoord")) {
        const tinygltf::Value& t = v.Get("texCoord");
        const double d = t.IsNumber() ? t.GetNumberAsDouble() : -1.0;
        if (!(d >= 0 && d <= 1024 && d == std::floor(d)))
            report.error(p + "/texCoord", "expected a TEXCOORD set index (an integer >= 0)");
    }
}

void checkMaterials(const tinygltf::Model& model, Reporter& report) {
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& m = model.materials[i];
        const std::string pointer = "/materials/" + std::to_string(i);
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4 || !allFinite(pbr.baseColorFactor))
            report.error(pointer + "/pbrMetallicRoughness/baseColorFactor",
                         "expected 4 finite numbers");
        if (!std::isfinite(pbr.metallicFactor) || pbr.metallicFactor < 0 || pbr.metallicFactor > 1)
            report.error(pointer + "/pbrMetallicRoughness/metallicFactor",
                         "expected a number from 0 to 1");
        if (!std::isfinite(pbr.roughnessFactor) || pbr.roughnessFactor < 0 ||
            pbr.roughnessFactor > 1)
            report.error(pointer + "/pbrMetallicRoughness/roughnessFactor",
                         "expected a number from 0 to 1");
        if (m.emissiveFactor.size() != 3 || !allFinite(m.emissiveFactor))
            report.error(pointer + "/emissiveFactor", "expected 3 finite numbers");
        if (m.normalTexture.index >= 0 && !std::isfinite(m.normalTexture.scale))
            report.error(pointer + "/normalTexture/scale", "expected a finite number");
        if (m.occlusionTexture.index >= 0 &&
            !(m.occlusionTexture.strength >= 0 && m.occlusionTexture.strength <= 1))
            report.error(pointer + "/occlusionTexture/strength", "expected a number from 0 to 1");
        if (m.alphaMode != "OPAQUE" && m.alphaMode != "MASK" && m.alphaMode != "BLEND")
            report.error(pointer + "/alphaMode",
                         "expected \"OPAQUE\", \"MASK\" or \"BLEND\", got \"" +
                             m.alphaMode.substr(0, 40) + "\"");
        if (!std::isfinite(m.alphaCutoff) || m.alphaCutoff < 0)
            report.error(pointer + "/alphaCutoff", "expected a finite number >= 0");
        const auto transform = [&](const auto& info, const std::string& name) {
            if (info.index >= 0) checkTextureTransform(info.extensions, pointer + name, report);
        };
        transform(pbr.baseColorTexture, "/pbrMetallicRoughness/baseColorTexture");
        transform(pbr.metallicRoughnessTexture, "/pbrMetallicRoughness/metallicRoughnessTexture");
        transform(m.normalTexture, "/normalTexture");
        transform(m.emissiveTexture, "/emissiveTexture");
        transform(m.occlusionTexture, "/occlusionTexture");
        if (const auto ext = m.extensions.find("KHR_materials_emissive_strength");
            ext != m.extensions.end() && ext->second.Has("emissiveStrength")) {
            const tinygltf::Value& strength = ext->second.Get("emissiveStrength");
            if (!strength.IsNumber() || !std::isfinite(strength.GetNumberAsDouble()) ||
                strength.GetNumberAsDouble() < 0)
                report.error(pointer + "/extensions/KHR_materials_emissive_strength/"
                                       "emissiveStrength",
                             "expected a finite number >= 0");
        }
    }
}

// Sampler filters and wrap modes must be the GL enums glTF allows (glTF 2.0 section 5.26).
void checkSamplers(const tinygltf::Model& model, Reporter& report) {
    const auto oneOf = [](int value, std::initializer_list<int> allowed) {
        for (int a : allowed)
            if (value == a) return true;
        return false;
    };
    for (std::size_t i = 0; i < model.samplers.size(); ++i) {
        const tinygltf::Sampler& s = model.samplers[i];
        const std::string pointer = "/samplers/" + std::to_string(i);
        if (s.magFilter != -1 && !oneOf(s.magFilter, {9728, 9729}))
            report.error(pointer + "/magFilter", "expected 9728 (NEAREST) or 9729 (LINEAR), got " +
                                                     std::to_string(s.magFilter));
        if (s.minFilter != -1 && !oneOf(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}))
            report.error(pointer + "/minFilter",
                         "expected 9728, 9729 or 9984 to 9987 (a GL minification filter), got " +
                             std::to_string(s.minFilter));
        for (const auto& [value, name] : {std::pair{s.wrapS, "wrapS"}, {s.wrapT, "wrapT"}})
            if (!oneOf(value, {33071, 33648, 10497}))
                report.error(pointer + "/" + name,
                             "expected 33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT) or 10497 "
                             "(REPEAT), got " +
                                 std::to_string(value));
    }
}

void checkPrimitiveModes(const tinygltf::Model& model, Reporter& report) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            const std::string pointer =
                "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
            if (primitive.mode < 0 || primitive.mode > 6)
                report.error(pointer + "/mode", "expected a primitive mode from 0 to 6, got " +
                                                    std::to_string(primitive.mode));
            if (primitive.attributes.find("POSITION") == primitive.attributes.end())
                report.error(pointer + "/attributes", "expected a POSITION attribute");
        }
}

} // namespace

bool validateModel(const tinygltf::Model& model, Reporter& report) {
    const int errorsBefore = report.errors;
    checkBufferViews(model, report);
    if (report.errors == errorsBefore) {
        for (std::size_t i = 0; i < model.accessors.size(); ++i)
            checkAccessor(model, int(i), report);
    }
    checkNodes(model, report);
    checkHierarchy(model, report);
    checkMaterials(model, report);
    checkSamplers(model, report);
    checkPrimitiveModes(model, report);
    return report.errors == errorsBefore;
}

} // namespace rmsc::gltf
