// Baking a glTF scene into triangle primitives (see gltf_geometry.hpp).
#include "scene/gltf_geometry.hpp"
#include "gltf_lights.hpp"
#include "gltf_rig_import.hpp"

#include "gltf_accessors.hpp"
#include "gltf_texcoord.hpp"
#include "gltf_validate.hpp"
#include "scene/mesh_pose.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

namespace rmsc::gltf {

namespace {

using SourcePrimitive = RigPrimitive;

// The TEXCOORD sets the textures of `material` read, as a pointer per set ("" = unused).
std::array<std::string, 2> texCoordUsers(const tinygltf::Model& model, int material) {
    std::array<std::string, 2> users;
    if (material < 0 || std::size_t(material) >= model.materials.size()) return users;
    const tinygltf::Material& m = model.materials[std::size_t(material)];
    const std::string pointer = "/materials/" + std::to_string(material);
    const auto use = [&](const auto& info, const std::string& name) {
        const int texCoord = textureTexCoord(info);
        if (info.index >= 0 && (texCoord == 0 || texCoord == 1) &&
            users[std::size_t(texCoord)].empty())
            users[std::size_t(texCoord)] = pointer + name;
    };
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    use(pbr.baseColorTexture, "/pbrMetallicRoughness/baseColorTexture");
    use(pbr.metallicRoughnessTexture, "/pbrMetallicRoughness/metallicRoughnessTexture");
    use(m.normalTexture, "/normalTexture");
    use(m.emissiveTexture, "/emissiveTexture");
    use(m.occlusionTexture, "/occlusionTexture");
    return users;
}

std::string primitivePointer(std::size_t mesh, std::size_t primitive) {
    return "/meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(primitive);
}

bool isTriangleMode(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

PrimitiveMode primitiveMode(int mode) {
    if (isTriangleMode(mode)) return PrimitiveMode::Triangles;
    return mode == TINYGLTF_MODE_POINTS ? PrimitiveMode::Points : PrimitiveMode::Lines;
}

// The number of indices an index list of `count` entries in glTF mode `mode` becomes (what
// toElements makes of it).
std::uint64_t elementIndexCount(std::uint64_t count, int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
    case TINYGLTF_MODE_LINE:
    case TINYGLTF_MODE_TRIANGLES:
        return count;
    case TINYGLTF_MODE_LINE_STRIP:
        return count < 2 ? 0 : (count - 1) * 2;
    case TINYGLTF_MODE_LINE_LOOP:
        return count < 2 ? 0 : count * 2;
    default: // strips and fans
        return count < 3 ? 0 : (count - 2) * 3;
    }
}

// Converts an index list of glTF mode `mode` (0 to 6; validated) to a list of points, line
// segments (pairs) or triangles (glTF 2.0 section 3.7.2.1, "Topology Types").
std::optional<std::vector<std::uint32_t>> toElements(const std::vector<std::uint32_t>& indices,
                                                     int mode, const std::string& pointer,
                                                     Reporter& report) {
    std::vector<std::uint32_t> out;
    const std::size_t n = indices.size();
    if (mode == TINYGLTF_MODE_POINTS) return indices;
    if (mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_LINE) {
        const std::size_t per = mode == TINYGLTF_MODE_LINE ? 2 : 3;
        if (n % per != 0) {
            report.error(pointer, std::to_string(n) + " indices (or vertices) do not form whole " +
                                      (per == 2 ? "lines" : "triangles") +
                                      ", expected a multiple of " + std::to_string(per));
            return std::nullopt;
        }
        return indices;
    }
    if (mode == TINYGLTF_MODE_LINE_STRIP || mode == TINYGLTF_MODE_LINE_LOOP) {
        if (n < 2) return out;
        out.reserve(std::size_t(elementIndexCount(n, mode)));
        for (std::size_t i = 0; i + 1 < n; ++i)
            out.insert(out.end(), {indices[i], indices[i + 1]});
        if (mode == TINYGLTF_MODE_LINE_LOOP) out.insert(out.end(), {indices[n - 1], indices[0]});
        return out;
    }
    if (n < 3) return out;
    out.reserve((n - 2) * 3);
    for (std::size_t i = 0; i + 2 < n; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Every other triangle is reversed to keep the strip's winding.
            const bool odd = i % 2 == 1;
            out.insert(out.end(),
                       {indices[i], indices[i + (odd ? 2 : 1)], indices[i + (odd ? 1 : 2)]});
        } else {
            out.insert(out.end(), {indices[i + 1], indices[i + 2], indices[0]});
        }
    }
    return out;
}

// JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1 (glTF 2.0 section 3.7.3.3, "Skinned Mesh
// Attributes"): joints VEC4 UNSIGNED_BYTE or UNSIGNED_SHORT, weights VEC4 FLOAT or normalized
// UNSIGNED_BYTE / UNSIGNED_SHORT. Each set needs both; joint indices are checked against the
// skin when posing (a mesh may be used by nodes with different skins).
bool readSkinAttributes(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                        std::size_t vertexCount, const std::string& pointer, Reporter& report,
                        SourcePrimitive& out) {
    std::vector<float> values;
    for (int set = 0; set < 2; ++set) {
        const std::string joints = "JOINTS_" + std::to_string(set);
        const std::string weights = "WEIGHTS_" + std::to_string(set);
        const auto j = prim.attributes.find(joints);
        const auto w = prim.attributes.find(weights);
        if (j == prim.attributes.end() && w == prim.attributes.end()) continue;
        if (j == prim.attributes.end() || w == prim.attributes.end()) {
            report.error(pointer + "/attributes",
                         "has " + (j == prim.attributes.end() ? weights : joints) + " without " +
                             (j == prim.attributes.end() ? joints : weights) +
                             ", expected both or neither");
            return false;
        }
        if (!readFloatAttribute(model, j->second, 4, kUint8 | kUint16, joints + " of " + pointer,
                                values, report))
            return false;
        out.joints[std::size_t(set)].resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            out.joints[std::size_t(set)][i] =
                glm::uvec4(unsigned(values[4 * i]), unsigned(values[4 * i + 1]),
                           unsigned(values[4 * i + 2]), unsigned(values[4 * i + 3]));
        if (!readFloatAttribute(model, w->second, 4, kFloat | kUnorm8 | kUnorm16,
                                weights + " of " + pointer, values, report))
            return false;
        out.weights[std::size_t(set)].resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            out.weights[std::size_t(set)][i] =
                glm::vec4(values[4 * i], values[4 * i + 1], values[4 * i + 2], values[4 * i + 3]);
    }
    return true;
}

// Morph targets (glTF 2.0 section 3.7.2.2, "Morph Targets"): POSITION, NORMAL and TANGENT
// deltas, VEC3 FLOAT (or the integer formats KHR_mesh_quantization allows for them), at most
// limits::kGltfMorphTargets per primitive, every primitive of a mesh with the same count.
bool readMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                      std::size_t vertexCount, bool quantized, const std::string& pointer,
                      Reporter& report, SourcePrimitive& out) {
    if (prim.targets.size() > std::size_t(limits::kGltfMorphTargets)) {
        report.error(pointer + "/targets",
                     "has " + std::to_string(prim.targets.size()) + " morph targets; at most " +
                         std::to_string(limits::kGltfMorphTargets) + " are supported (the limit)");
        return false;
    }
    const unsigned positionFormats =
        quantized ? kFloat | kSnorm8 | kSnorm16 | kSint8 | kSint16 : kFloat;
    const unsigned directionFormats = quantized ? kFloat | kSnorm8 | kSnorm16 : kFloat;
    std::vector<float> values;
    out.targets.resize(prim.targets.size());
    for (std::size_t t = 0; t < prim.targets.size(); ++t) {
        const std::string targetPointer = pointer + "/targets/" + std::to_string(t);
        for (const auto& [name, accessor] : prim.targets[t]) {
            std::vector<glm::vec3>* into = name == "POSITION"  ? &out.targets[t].positions
                                           : name == "NORMAL"  ? &out.targets[t].normals
                                           : name == "TANGENT" ? &out.targets[t].tangents
                                                               : nullptr;
            if (!into) {
                report.warning(targetPointer + "/" + name,
                               "morph target attribute " + name + " is not supported; ignored");
                continue;
            }
            if (accessor < 0 || std::size_t(accessor) >= model.accessors.size()) {
                report.error(targetPointer + "/" + name, "refers to a missing accessor");
                return false;
            }
            const std::size_t count = model.accessors[std::size_t(accessor)].count;
            if (count != vertexCount) {
                report.error(targetPointer + "/" + name, "accessor has " + std::to_string(count) +
                                                             " elements but POSITION has " +
                                                             std::to_string(vertexCount) +
                                                             ", expected the same count");
                return false;
            }
            if (!readFloatAttribute(model, accessor, 3,
                                    name == "POSITION" ? positionFormats : directionFormats,
                                    name + " of " + targetPointer, values, report))
                return false;
            into->resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                (*into)[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
        }
    }
    return true;
}

bool readPrimitive(const tinygltf::Model& model, std::size_t meshIndex, std::size_t primIndex,
                   Reporter& report, SourcePrimitive& out) {
    const tinygltf::Primitive& prim = model.meshes[meshIndex].primitives[primIndex];
    const std::string pointer = primitivePointer(meshIndex, primIndex);
    const auto accessorOf = [&](const char* name) -> int {
        const auto it = prim.attributes.find(name);
        if (it == prim.attributes.end()) return -1;
        return it->second >= 0 && std::size_t(it->second) < model.accessors.size() ? it->second
                                                                                   : -2;
    };
    const int positionAccessor = accessorOf("POSITION");
    if (positionAccessor < 0) {
        report.error(pointer + "/attributes/POSITION", "expected a valid POSITION accessor");
        return false;
    }
    const std::size_t vertexCount = model.accessors[std::size_t(positionAccessor)].count;
    for (const auto& [name, accessor] : prim.attributes) {
        if (accessor < 0 || std::size_t(accessor) >= model.accessors.size()) {
            report.error(pointer + "/attributes/" + name, "refers to a missing accessor");
            return false;
        }
        const std::size_t count = model.accessors[std::size_t(accessor)].count;
        if (count != vertexCount) {
            report.error(pointer + "/attributes/" + name,
                         "accessor has " + std::to_string(count) + " elements but POSITION has " +
                             std::to_string(vertexCount) + ", expected the same count");
            return false;
        }
    }
    // glTF 2.0 section 3.7.2.1, and what KHR_mesh_quantization adds when the file uses it.
    const bool quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                     "KHR_mesh_quantization") != model.extensionsUsed.end();
    const std::string hint =
        quantized ? "" : "KHR_mesh_quantization allows more, but the file does not use it";
    const unsigned allIntegers =
        kUnorm8 | kUnorm16 | kSnorm8 | kSnorm16 | kUint8 | kSint8 | kUint16 | kSint16;
    const unsigned positionFormats = quantized ? kFloat | allIntegers : kFloat;
    const unsigned directionFormats = quantized ? kFloat | kSnorm8 | kSnorm16 : kFloat;
    const unsigned uvFormats = quantized ? kFloat | allIntegers : kFloat | kUnorm8 | kUnorm16;
    std::vector<float> values;
    if (!readFloatAttribute(model, positionAccessor, 3, positionFormats, "POSITION of " + pointer,
                            values, report, hint))
        return false;
    out.positions.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
        out.positions[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};

    if (const int normalAccessor = accessorOf("NORMAL"); normalAccessor >= 0) {
        if (!readFloatAttribute(model, normalAccessor, 3, directionFormats, "NORMAL of " + pointer,
                                values, report, hint))
            return false;
        out.normals.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            out.normals[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    }
    const std::array<std::string, 2> uvUsers = texCoordUsers(model, prim.material);
    for (int set = 0; set < 2; ++set) {
        const std::string name = "TEXCOORD_" + std::to_string(set);
        std::vector<glm::vec2>& uvs = set == 0 ? out.uvs : out.uvs1;
        uvs.assign(vertexCount, glm::vec2(0.0f));
        const int uvAccessor = accessorOf(name.c_str());
        if (uvAccessor < 0) {
            if (!uvUsers[std::size_t(set)].empty()) {
                report.error(pointer + "/attributes",
                             "the material's texture " + uvUsers[std::size_t(set)] + " reads " +
                                 name + ", expected the primitive to have a " + name +
                                 " attribute");
                return false;
            }
            continue;
        }
        if (!readFloatAttribute(model, uvAccessor, 2, uvFormats, name + " of " + pointer, values,
                                report, hint))
            return false;
        for (std::size_t i = 0; i < vertexCount; ++i)
            uvs[i] = {values[2 * i], values[2 * i + 1]};
    }
    if (const int tangentAccessor = accessorOf("TANGENT"); tangentAccessor >= 0) {
        if (!readFloatAttribute(model, tangentAccessor, 4, directionFormats,
                                "TANGENT of " + pointer, values, report, hint))
            return false;
        out.tangents.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            out.tangents[i] = {values[4 * i], values[4 * i + 1], values[4 * i + 2],
                               values[4 * i + 3] < 0.0f ? -1.0f : 1.0f};
        }
    }
    // COLOR_0 (glTF 2.0 section 3.7.2.1): VEC3 or VEC4, FLOAT or normalized UNSIGNED_BYTE /
    // UNSIGNED_SHORT, linear; multiplies the base colour.
    if (const int colorAccessor = accessorOf("COLOR_0"); colorAccessor >= 0) {
        const int components =
            model.accessors[std::size_t(colorAccessor)].type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
        if (!readFloatAttribute(model, colorAccessor, components, kFloat | kUnorm8 | kUnorm16,
                                "COLOR_0 of " + pointer, values, report))
            return false;
        out.colors.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const float* c = &values[std::size_t(components) * i];
            out.colors[i] = glm::vec4(c[0], c[1], c[2], components == 4 ? c[3] : 1.0f);
        }
    }
    if (!readSkinAttributes(model, prim, vertexCount, pointer, report, out)) return false;
    if (!readMorphTargets(model, prim, vertexCount, quantized, pointer, report, out)) return false;
    if (prim.material >= 0 && std::size_t(prim.material) < model.materials.size()) {
        const int set = textureTexCoord(model.materials[std::size_t(prim.material)].normalTexture);
        out.tangentUvSet = set == 1 ? 1 : 0;
    }

    std::vector<std::uint32_t> indices;
    if (prim.indices >= 0) {
        if (std::size_t(prim.indices) >= model.accessors.size()) {
            report.error(pointer + "/indices", "refers to a missing accessor");
            return false;
        }
        if (!readIndices(model, prim.indices, "indices of " + pointer, indices, report))
            return false;
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] >= vertexCount) {
                report.error("/accessors/" + std::to_string(prim.indices),
                             "index " + std::to_string(indices[i]) + " at element " +
                                 std::to_string(i) + " (indices of " + pointer +
                                 ") is not less than the vertex count " +
                                 std::to_string(vertexCount));
                return false;
            }
        }
    } else {
        indices.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            indices[i] = std::uint32_t(i);
    }
    auto elements = toElements(indices, prim.mode, pointer, report);
    if (!elements) return false;
    out.indices = std::move(*elements);
    out.mode = primitiveMode(prim.mode);
    if (out.indices.empty()) {
        report.warning(pointer, std::string("primitive has no ") +
                                    (out.mode == PrimitiveMode::Triangles ? "triangles"
                                     : out.mode == PrimitiveMode::Lines   ? "lines"
                                                                          : "points") +
                                    "; skipped");
        return true;
    }
    out.material = prim.material >= 0 && std::size_t(prim.material) < model.materials.size()
                       ? prim.material
                       : -1;
    out.drawable = true;
    return true;
}

// The node as the rig keeps it: its rest transform, what it draws and its own morph weights.
RigNode rigNode(const tinygltf::Node& node) {
    RigNode out;
    out.name = node.name;
    if (node.matrix.size() == 16) {
        out.hasMatrix = true;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                out.matrix[c][r] = node.matrix[std::size_t(c * 4 + r)];
    }
    if (node.translation.size() == 3)
        out.translation = glm::dvec3(node.translation[0], node.translation[1], node.translation[2]);
    if (node.rotation.size() == 4) {
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        out.rotation = length > 1e-6 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
    }
    if (node.scale.size() == 3) out.scale = glm::dvec3(node.scale[0], node.scale[1], node.scale[2]);
    out.mesh = node.mesh;
    out.skin = node.skin;
    out.camera = node.camera;
    for (double w : node.weights)
        out.weights.push_back(float(w));
    out.children = node.children;
    return out;
}

} // namespace

bool bakePrimitive(const RigPrimitive& source, const glm::dmat4& world,
                   const std::string& nodePointer, Reporter& report, MeshAsset& asset) {
    const glm::dmat3 linear(world);
    const double det = glm::determinant(linear);
    const glm::dmat3 normalMatrix = std::abs(det) > 1e-300 ? glm::inverseTranspose(linear) : linear;
    MeshPrimitive out;
    out.material = source.material;
    out.vertices.resize(source.positions.size());
    std::vector<glm::vec3> positions(source.positions.size());
    for (std::size_t i = 0; i < source.positions.size(); ++i) {
        const glm::dvec3 p = glm::dvec3(world * glm::dvec4(glm::dvec3(source.positions[i]), 1.0));
        positions[i] = glm::vec3(p);
        if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) ||
            !std::isfinite(positions[i].z)) {
            report.error(nodePointer, "the node's transform makes positions infinite or NaN");
            return false;
        }
    }
    out.indices = source.indices;
    out.mode = source.mode;
    const bool triangles = source.mode == PrimitiveMode::Triangles;
    if (det < 0 && triangles)
        for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3)
            std::swap(out.indices[t + 1], out.indices[t + 2]);
    std::vector<glm::vec3> normals;
    if (source.normals.empty() && !triangles) {
        normals.assign(positions.size(), glm::vec3(0.0f)); // nothing to compute them from
    } else if (source.normals.empty()) {
        normals = smoothNormals(positions, out.indices);
    } else {
        normals.resize(source.normals.size());
        for (std::size_t i = 0; i < normals.size(); ++i) {
            const glm::dvec3 n = normalMatrix * glm::dvec3(source.normals[i]);
            const double length = glm::length(n);
            normals[i] = length > 1e-12 && std::isfinite(length) ? glm::vec3(n / length)
                                                                 : glm::vec3(0.0f, 1.0f, 0.0f);
        }
    }
    std::vector<glm::vec4> tangents;
    if (!triangles) {
        tangents.assign(positions.size(), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)); // drawn unlit
    } else if (source.tangents.empty()) {
        tangents = generateTangents(
            positions, normals, source.tangentUvSet == 1 ? source.uvs1 : source.uvs, out.indices);
    } else {
        // Tangents transform like positions (not like normals); a mirroring transform flips
        // the bitangent's handedness, as it flips the cross product n x t.
        tangents.resize(source.tangents.size());
        for (std::size_t i = 0; i < tangents.size(); ++i) {
            glm::dvec3 t = linear * glm::dvec3(glm::vec3(source.tangents[i]));
            const glm::dvec3 n(normals[i]);
            t -= n * glm::dot(n, t);
            const double length = glm::length(t);
            const glm::vec3 unit = length > 1e-12 && std::isfinite(length)
                                       ? glm::vec3(t / length)
                                       : anyPerpendicular(normals[i]);
            tangents[i] = glm::vec4(unit, det < 0 ? -source.tangents[i].w : source.tangents[i].w);
        }
    }
    for (std::size_t i = 0; i < out.vertices.size(); ++i)
        out.vertices[i] = {
            positions[i],  normals[i],
            source.uvs[i], source.uvs1[i],
            tangents[i],   source.colors.empty() ? glm::vec4(1.0f) : source.colors[i]};
    asset.primitives.push_back(std::move(out));
    return true;
}

namespace {

// The scene drawn: `chosen` when it is not -1, else the default scene, scene 0, or -1 (every
// node without a parent) for a file without scenes.
int drawnScene(const tinygltf::Model& model, int chosen) {
    if (chosen >= 0) return chosen;
    if (model.scenes.empty()) return -1;
    return model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size()
               ? model.defaultScene
               : 0;
}

// The nodes to start from: those of scene `scene`, or every node without a parent for -1.
std::vector<int> rootNodes(const tinygltf::Model& model, int scene) {
    if (scene >= 0) return model.scenes[std::size_t(scene)].nodes;
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const tinygltf::Node& node : model.nodes)
        for (int child : node.children)
            if (child >= 0 && std::size_t(child) < model.nodes.size())
                isChild[std::size_t(child)] = 1;
    std::vector<int> roots;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

} // namespace

glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(glm::cross(n, axis), n));
}

// Eric Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh" (Terathon
// Software, 2001): per triangle, solve the edge vectors for the directions of +u (sdir) and
// +v (tdir), sum them per vertex, Gram-Schmidt the tangent against the normal. glTF's v axis
// points down the image while a normal map's +y points up it, so the bitangent the map expects
// is -dP/dv (as in the Khronos glTF sample viewer); the handedness w is taken against that.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs,
                                        const std::vector<std::uint32_t>& triangles) {
    const std::size_t count = positions.size();
    std::vector<glm::dvec3> uDirections(count, glm::dvec3(0.0)),
        vDirections(count, glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const std::uint32_t i0 = triangles[t], i1 = triangles[t + 1], i2 = triangles[t + 2];
        if (i0 >= count || i1 >= count || i2 >= count || i0 >= uvs.size() || i1 >= uvs.size() ||
            i2 >= uvs.size())
            continue;
        const glm::dvec3 e1 = glm::dvec3(positions[i1]) - glm::dvec3(positions[i0]);
        const glm::dvec3 e2 = glm::dvec3(positions[i2]) - glm::dvec3(positions[i0]);
        const glm::dvec2 d1 = glm::dvec2(uvs[i1]) - glm::dvec2(uvs[i0]);
        const glm::dvec2 d2 = glm::dvec2(uvs[i2]) - glm::dvec2(uvs[i0]);
        const double det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(det) > 1e-20) || !std::isfinite(det)) continue; // no UV area
        const glm::dvec3 uDir = (e1 * d2.y - e2 * d1.y) / det;
        const glm::dvec3 vDir = (e2 * d1.x - e1 * d2.x) / det;
        for (std::uint32_t i : {i0, i1, i2}) {
            uDirections[i] += uDir;
            vDirections[i] += vDir;
        }
    }
    std::vector<glm::vec4> tangents(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 n(normals[i]);
        glm::dvec3 t = uDirections[i] - n * glm::dot(n, uDirections[i]);
        const double length = glm::length(t);
        if (!(length > 1e-12) || !std::isfinite(length)) {
            tangents[i] = glm::vec4(anyPerpendicular(normals[i]), 1.0f);
            continue;
        }
        t /= length;
        const double handedness = glm::dot(glm::cross(n, t), -vDirections[i]);
        tangents[i] = glm::vec4(glm::vec3(t), handedness < 0.0 ? -1.0f : 1.0f);
    }
    return tangents;
}

std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions,
                                     const std::vector<std::uint32_t>& triangles) {
    std::vector<glm::dvec3> sums(positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const std::uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
        const glm::dvec3 pa(positions[a]), pb(positions[b]), pc(positions[c]);
        const glm::dvec3 n = glm::cross(pb - pa, pc - pa); // length = twice the area
        sums[a] += n;
        sums[b] += n;
        sums[c] += n;
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const double length = glm::length(sums[i]);
        normals[i] = length > 0 && std::isfinite(length) ? glm::vec3(sums[i] / length)
                                                         : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return normals;
}

namespace {

// Walks the scene from its roots, depth first: lists the nodes that draw a mesh, in drawing
// order, and the first node placing each camera. Reads no vertex data.
bool walkNodes(const tinygltf::Model& model, Reporter& report, MeshRig& rig) {
    struct Visit {
        int node;
        int depth;
    };
    std::vector<Visit> stack;
    for (auto it = rig.roots.rbegin(); it != rig.roots.rend(); ++it)
        stack.push_back({*it, 1});
    std::vector<char> visited(model.nodes.size(), 0);
    while (!stack.empty()) {
        const Visit visit = stack.back();
        stack.pop_back();
        const std::string pointer = "/nodes/" + std::to_string(visit.node);
        if (visit.node < 0 || std::size_t(visit.node) >= model.nodes.size()) {
            report.error(pointer, "node does not exist");
            return false;
        }
        if (visited[std::size_t(visit.node)] || visit.depth > kMaxNodeDepth) {
            report.error(pointer, "node reached twice or nested too deeply, expected a tree");
            return false;
        }
        visited[std::size_t(visit.node)] = 1;
        const tinygltf::Node& node = model.nodes[std::size_t(visit.node)];
        if (node.rotation.size() == 4 &&
            !(glm::length(glm::dvec4(node.rotation[0], node.rotation[1], node.rotation[2],
                                     node.rotation[3])) > 1e-6)) {
            report.error(pointer + "/rotation", "expected a unit quaternion, got length 0");
            return false;
        }
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= model.meshes.size()) {
                report.error(pointer + "/mesh", "refers to a missing mesh");
                return false;
            }
            rig.instances.push_back(visit.node);
        }
        if (node.camera >= 0 && std::size_t(node.camera) < rig.cameras.size() &&
            rig.cameras[std::size_t(node.camera)].node < 0)
            rig.cameras[std::size_t(node.camera)].node = visit.node;
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            stack.push_back({*it, visit.depth + 1});
    }
    return true;
}
// The vertices and triangle indices one instance of mesh `m` adds, from its accessors' counts
// (what readPrimitive will read and toElements make of it). Accessor references were checked.
void meshCounts(const tinygltf::Model& model, std::size_t m, std::uint64_t& vertices,
                std::uint64_t& indices) {
    vertices = indices = 0;
    for (const tinygltf::Primitive& prim : model.meshes[m].primitives) {
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end() || position->second < 0 ||
            std::size_t(position->second) >= model.accessors.size())
            continue; // refused by readPrimitive
        const std::uint64_t count = model.accessors[std::size_t(position->second)].count;
        std::uint64_t listed = count;
        if (prim.indices >= 0 && std::size_t(prim.indices) < model.accessors.size())
            listed = model.accessors[std::size_t(prim.indices)].count;
        vertices += count;
        indices += elementIndexCount(listed, prim.mode);
    }
}

// Takes every instance's vertices and indices out of the budget, in drawing order, before
// anything is read: a file whose accessors claim more than the budget is refused at the node
// that goes over, whatever its buffers hold (an accessor without a buffer view is all zeros
// and costs nothing in the file).
bool countInstances(const tinygltf::Model& model, const std::vector<int>& instances,
                    Allowance& vertices, Allowance& indices, Reporter& report) {
    std::vector<std::uint64_t> meshVertices(model.meshes.size()), meshIndices(model.meshes.size());
    std::vector<char> counted(model.meshes.size(), 0);
    for (const int node : instances) {
        const std::size_t m = std::size_t(model.nodes[std::size_t(node)].mesh);
        if (!counted[m]) {
            meshCounts(model, m, meshVertices[m], meshIndices[m]);
            counted[m] = 1;
        }
        const std::string pointer = "/nodes/" + std::to_string(node);
        for (Allowance* allowance : {&vertices, &indices}) {
            const std::uint64_t amount = allowance == &vertices ? meshVertices[m] : meshIndices[m];
            if (!allowance->take(amount)) {
                const std::uint64_t needed =
                    amount > std::numeric_limits<std::uint64_t>::max() - allowance->used
                        ? std::numeric_limits<std::uint64_t>::max()
                        : allowance->used + amount;
                report.error(pointer, "instancing /meshes/" + std::to_string(m) +
                                          " here brings the file's scene to " +
                                          allowance->refusal(needed));
                return false;
            }
        }
    }
    return true;
}

// Every primitive of mesh `m` has the same number of morph targets (glTF 2.0 section 3.7.2.2),
// which mesh.weights, when given, matches; the mesh's default weights are kept in the rig.
bool checkMeshWeights(const tinygltf::Model& model, std::size_t m, MeshRig& rig, Reporter& report) {
    const tinygltf::Mesh& mesh = model.meshes[m];
    const std::string pointer = "/meshes/" + std::to_string(m);
    const std::size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    for (std::size_t p = 1; p < mesh.primitives.size(); ++p)
        if (mesh.primitives[p].targets.size() != targets) {
            report.error(pointer + "/primitives/" + std::to_string(p) + "/targets",
                         "has " + std::to_string(mesh.primitives[p].targets.size()) +
                             " morph targets but primitive 0 has " + std::to_string(targets) +
                             ", expected the same number");
            return false;
        }
    if (!mesh.weights.empty() && mesh.weights.size() != targets) {
        report.error(pointer + "/weights", "has " + std::to_string(mesh.weights.size()) +
                                               " weights for " + std::to_string(targets) +
                                               " morph targets, expected one per target");
        return false;
    }
    std::vector<float>& weights = rig.meshes[m].weights;
    weights.assign(targets, 0.0f);
    for (std::size_t i = 0; i < mesh.weights.size(); ++i)
        weights[i] = float(mesh.weights[i]);
    return true;
}

} // namespace

bool buildGeometry(const tinygltf::Model& model, int scene, Allowance& vertices, Allowance& indices,
                   Reporter& report, MeshAsset& asset) {
    auto rig = std::make_shared<MeshRig>();
    for (const tinygltf::Node& node : model.nodes)
        rig->nodes.push_back(rigNode(node));
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (int child : model.nodes[n].children)
            if (child >= 0 && std::size_t(child) < model.nodes.size())
                rig->nodes[std::size_t(child)].parent = int(n);
    if (scene >= 0 && std::size_t(scene) >= model.scenes.size()) {
        std::string names;
        for (std::size_t s = 0; s < model.scenes.size(); ++s)
            names += (s ? ", " : "") + std::to_string(s) +
                     (model.scenes[s].name.empty() ? "" : " \"" + model.scenes[s].name + "\"");
        report.error("/scenes", "there is no scene " + std::to_string(scene) + "; the file has " +
                                    (model.scenes.empty() ? "no scenes" : "scenes " + names));
        return false;
    }
    rig->scene = drawnScene(model, scene);
    rig->roots = rootNodes(model, rig->scene);
    for (const tinygltf::Scene& s : model.scenes)
        rig->sceneNames.push_back(s.name);
    if (!readRigExtras(model, report, *rig)) return false;
    if (!walkNodes(model, report, *rig)) return false;
    if (!countInstances(model, rig->instances, vertices, indices, report)) return false;
    // Each mesh is read once, when first instanced.
    rig->meshes.resize(model.meshes.size());
    std::vector<char> read(model.meshes.size(), 0);
    for (const int node : rig->instances) {
        const std::size_t m = std::size_t(model.nodes[std::size_t(node)].mesh);
        if (read[m]) continue;
        read[m] = 1;
        RigMesh& mesh = rig->meshes[m];
        mesh.primitives.resize(model.meshes[m].primitives.size());
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
            if (!readPrimitive(model, m, p, report, mesh.primitives[p])) return false;
        if (!checkMeshWeights(model, m, *rig, report)) return false;
    }
    // The lights, placed by their nodes at rest.
    const std::vector<glm::dmat4> worlds = poseNodeWorlds(*rig, {});
    std::vector<int> stack(rig->roots.rbegin(), rig->roots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model.nodes[std::size_t(n)];
        addNodeLight(model, node, worlds[std::size_t(n)], "/nodes/" + std::to_string(n), report,
                     asset);
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            stack.push_back(*it);
    }
    asset.rig = rig;
    if (!bakePose(*rig, {}, report, asset)) return false;
    if (asset.primitives.empty())
        report.warning("", "the file's scene contains no triangles, lines or points");
    return true;
}

} // namespace rmsc::gltf
