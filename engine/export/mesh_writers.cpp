// The four mesh formats. glTF JSON is built with nlohmann-json; the buffers are little-endian
// as both glTF and STL require (rmsc builds on little-endian machines only).
#include "export/mesh_writers.hpp"

#include "core/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>

namespace rmsc {
namespace {

template <class T> void append(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t a = std::uint8_t(bytes[i]);
        const std::uint32_t b = i + 1 < bytes.size() ? std::uint8_t(bytes[i + 1]) : 0;
        const std::uint32_t c = i + 2 < bytes.size() ? std::uint8_t(bytes[i + 2]) : 0;
        const std::uint32_t v = (a << 16) | (b << 8) | c;
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

// One glTF primitive: the triangles of one material, with vertices of their own (numbered from
// 0 in first-use order), and whether smooth operations blended the base colour of any of them
// away from the material's.
struct Primitive {
    std::vector<std::uint32_t> vertices; // mesh vertex of each primitive vertex
    std::vector<std::uint32_t> indices;  // into `vertices`, three per triangle
    bool blended = false;
};

std::vector<Primitive> primitivesOf(const MeshFile& file) {
    const ExportMesh& mesh = file.mesh;
    std::vector<Primitive> out(file.materials.size());
    std::vector<std::uint32_t> local(mesh.positions.size(), ~0u);
    for (std::uint32_t m = 0; m < out.size(); ++m) {
        Primitive& primitive = out[m];
        const glm::vec3 own = file.materials[m].baseColor;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (mesh.triangleMaterial[t] != m) continue;
            for (std::uint32_t v : mesh.triangles[t]) {
                if (local[v] == ~0u) {
                    local[v] = std::uint32_t(primitive.vertices.size());
                    primitive.vertices.push_back(v);
                    if (v < mesh.colors.size() &&
                        glm::any(
                            glm::greaterThan(glm::abs(mesh.colors[v] - own), glm::vec3(1e-3f))))
                        primitive.blended = true;
                }
                primitive.indices.push_back(local[v]);
            }
        }
        for (std::uint32_t v : primitive.vertices)
            local[v] = ~0u;
    }
    return out;
}

nlohmann::json vec(glm::vec3 v) {
    return nlohmann::json::array({v.x, v.y, v.z});
}

} // namespace

bool meshFormatOf(const std::filesystem::path& path, MeshFormat& format) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".gltf")
        format = MeshFormat::Gltf;
    else if (ext == ".glb")
        format = MeshFormat::Glb;
    else if (ext == ".obj")
        format = MeshFormat::Obj;
    else if (ext == ".stl")
        format = MeshFormat::Stl;
    else
        return false;
    return true;
}

std::string gltfBytes(const MeshFile& file, bool binary) {
    const ExportMesh& mesh = file.mesh;
    const std::vector<Primitive> parts = primitivesOf(file);
    std::string buffer;
    nlohmann::json views = nlohmann::json::array();
    nlohmann::json accessors = nlohmann::json::array();
    auto addView = [&](std::size_t offset, std::size_t length, int target) {
        views.push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"target", target}});
        return int(views.size()) - 1;
    };
    // A VEC3 float accessor of `value(v)` for the primitive's vertices.
    auto addVec3 = [&](const Primitive& primitive, bool bounds, auto value) {
        const std::size_t offset = buffer.size();
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (std::uint32_t v : primitive.vertices) {
            const glm::vec3 x = value(v);
            append(buffer, x);
            lo = glm::min(lo, x);
            hi = glm::max(hi, x);
        }
        nlohmann::json accessor = {{"bufferView", addView(offset, buffer.size() - offset, 34962)},
                                   {"componentType", 5126},
                                   {"count", primitive.vertices.size()},
                                   {"type", "VEC3"}};
        if (bounds) {
            accessor["min"] = vec(lo);
            accessor["max"] = vec(hi);
        }
        accessors.push_back(accessor);
        return int(accessors.size()) - 1;
    };
    nlohmann::json primitives = nlohmann::json::array();
    for (std::uint32_t m = 0; m < parts.size(); ++m) {
        const Primitive& primitive = parts[m];
        if (primitive.indices.empty()) continue;
        nlohmann::json attributes = {
            {"POSITION",
             addVec3(primitive, true, [&](std::uint32_t v) { return mesh.positions[v]; })},
            {"NORMAL",
             addVec3(primitive, false, [&](std::uint32_t v) { return mesh.normals[v]; })}};
        // COLOR_0 multiplies the material's base colour (glTF 2.0, 3.7.2.1 and 3.9.2): the
        // blended colour itself, with the material's factor white.
        if (primitive.blended)
            attributes["COLOR_0"] = addVec3(primitive, false, [&](std::uint32_t v) {
                return glm::clamp(mesh.colors[v], glm::vec3(0.0f), glm::vec3(1.0f));
            });
        const std::size_t offset = buffer.size();
        for (std::uint32_t i : primitive.indices)
            append(buffer, i);
        accessors.push_back({{"bufferView", addView(offset, buffer.size() - offset, 34963)},
                             {"componentType", 5125},
                             {"count", primitive.indices.size()},
                             {"type", "SCALAR"},
                             {"min", {0}},
                             {"max", {primitive.vertices.size() - 1}}});
        primitives.push_back({{"attributes", attributes},
                              {"indices", int(accessors.size()) - 1},
                              {"material", m},
                              {"mode", 4}});
    }
    nlohmann::json materials = nlohmann::json::array();
    for (std::uint32_t m = 0; m < file.materials.size(); ++m) {
        const Material& material = file.materials[m];
        const glm::vec3 factor = parts[m].blended ? glm::vec3(1.0f) : material.baseColor;
        nlohmann::json entry = {{"pbrMetallicRoughness",
                                 {{"baseColorFactor", {factor.x, factor.y, factor.z, 1.0}},
                                  {"metallicFactor", material.metallic},
                                  {"roughnessFactor", material.roughness}}}};
        if (!material.name.empty()) entry["name"] = material.name;
        if (glm::any(glm::greaterThan(material.emissive, glm::vec3(0.0f)))) {
            const float peak =
                std::max(material.emissive.x, std::max(material.emissive.y, material.emissive.z));
            // emissiveFactor is at most 1; KHR_materials_emissive_strength would carry more.
            entry["emissiveFactor"] = vec(material.emissive / std::max(peak, 1.0f));
        }
        materials.push_back(entry);
    }
    while (buffer.size() % 4)
        buffer += '\0';
    nlohmann::json bufferEntry = {{"byteLength", buffer.size()}};
    if (!binary) bufferEntry["uri"] = "data:application/octet-stream;base64," + base64(buffer);
    nlohmann::json doc = {
        {"asset", {{"version", "2.0"}, {"generator", "rmsc export"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}, {"name", file.name}}}},
        {"meshes", {{{"name", file.name}, {"primitives", primitives}}}},
        {"materials", materials},
        {"buffers", {bufferEntry}},
        {"bufferViews", views},
        {"accessors", accessors},
    };
    std::string json = doc.dump(binary ? -1 : 1);
    if (!binary) return json + "\n";
    while (json.size() % 4)
        json += ' ';
    // GLB: a 12-byte header, then the JSON and BIN chunks (glTF 2.0 spec, "Binary glTF Layout").
    std::string out;
    append(out, std::uint32_t(0x46546C67));
    append(out, std::uint32_t(2));
    append(out, std::uint32_t(12 + 8 + json.size() + 8 + buffer.size()));
    append(out, std::uint32_t(json.size()));
    append(out, std::uint32_t(0x4E4F534A));
    out += json;
    append(out, std::uint32_t(buffer.size()));
    append(out, std::uint32_t(0x004E4942));
    out += buffer;
    return out;
}

std::string objText(const MeshFile& file, const std::string& mtlFileName) {
    const ExportMesh& mesh = file.mesh;
    std::string out = "# rmsc export\nmtllib " + mtlFileName + "\no " + file.name + "\n";
    char line[160];
    // Vertex colours as the common "v x y z r g b" extension, the blended base colour.
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        const glm::vec3 c = v < mesh.colors.size() ? mesh.colors[v] : glm::vec3(0.8f);
        std::snprintf(line, sizeof line, "v %.7g %.7g %.7g %.4g %.4g %.4g\n", p.x, p.y, p.z, c.x,
                      c.y, c.z);
        out += line;
    }
    for (glm::vec3 n : mesh.normals) {
        std::snprintf(line, sizeof line, "vn %.6g %.6g %.6g\n", n.x, n.y, n.z);
        out += line;
    }
    for (std::uint32_t m = 0; m < file.materials.size(); ++m) {
        out += "usemtl material" + std::to_string(m) + "\n";
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (mesh.triangleMaterial[t] != m) continue;
            const auto& tri = mesh.triangles[t];
            std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", tri[0] + 1, tri[0] + 1,
                          tri[1] + 1, tri[1] + 1, tri[2] + 1, tri[2] + 1);
            out += line;
        }
    }
    return out;
}

std::string mtlText(const MeshFile& file) {
    std::string out = "# rmsc export\n";
    char line[160];
    for (std::uint32_t m = 0; m < file.materials.size(); ++m) {
        const Material& material = file.materials[m];
        out += "newmtl material" + std::to_string(m) + "\n";
        if (!material.name.empty()) out += "# " + material.name + "\n";
        std::snprintf(line, sizeof line, "Kd %.4g %.4g %.4g\nKe %.4g %.4g %.4g\nPr %.4g\nPm %.4g\n",
                      material.baseColor.x, material.baseColor.y, material.baseColor.z,
                      material.emissive.x, material.emissive.y, material.emissive.z,
                      material.roughness, material.metallic);
        out += line;
    }
    return out;
}

std::string stlBytes(const MeshFile& file) {
    const ExportMesh& mesh = file.mesh;
    std::string out(80, '\0');
    std::memcpy(out.data(), "rmsc export", 11);
    append(out, std::uint32_t(mesh.triangles.size()));
    for (const auto& tri : mesh.triangles) {
        const glm::vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                        c = mesh.positions[tri[2]];
        glm::vec3 n = glm::cross(b - a, c - a);
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f);
        append(out, n);
        append(out, a);
        append(out, b);
        append(out, c);
        append(out, std::uint16_t(0));
    }
    return out;
}

bool writeMeshFile(const std::filesystem::path& path, MeshFormat format, const MeshFile& file,
                   const std::atomic<bool>* cancel, std::string& error) {
    auto save = [&](const std::filesystem::path& target, const std::string& bytes) {
        return replaceFileAtomically(target, false, error, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            if (!out) {
                error = tmp.parent_path().string() + ": cannot create a file there";
                return false;
            }
            // In pieces, so an interrupt while writing a large file stops it (and the temporary
            // file is removed).
            const std::size_t piece = std::size_t(1) << 22;
            for (std::size_t at = 0; at < bytes.size(); at += piece) {
                if (cancel && cancel->load()) {
                    error = "interrupted";
                    return false;
                }
                out.write(bytes.data() + at, std::streamsize(std::min(piece, bytes.size() - at)));
            }
            out.flush();
            if (!out) {
                error = target.string() + ": write failed (disk full?)";
                return false;
            }
            return true;
        });
    };
    switch (format) {
    case MeshFormat::Gltf:
        return save(path, gltfBytes(file, false));
    case MeshFormat::Glb:
        return save(path, gltfBytes(file, true));
    case MeshFormat::Stl:
        return save(path, stlBytes(file));
    case MeshFormat::Obj: {
        std::filesystem::path mtl = path;
        mtl.replace_extension(".mtl");
        return save(mtl, mtlText(file)) && save(path, objText(file, mtl.filename().string()));
    }
    }
    return false;
}

} // namespace rmsc
