// glTF accessors: element sizes, the overflow-checked range check of an accessor against its
// buffer view, and typed reads of vertex attributes and indices that refuse unexpected types,
// non-finite values and sparse indices out of order.
#pragma once

#include "core/limits.hpp"
#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rmsc::gltf {

constexpr std::uint64_t kMaxVertices = limits::kGltfVertices; // per accessor and per asset
constexpr std::uint64_t kMaxIndices = limits::kGltfIndices;   // per accessor and per asset

// Bytes per component (0 for a component type glTF accessors may not use).
int componentSize(int componentType);
// Components per element (0 for an unknown type).
int componentCount(int type);
// Bytes per element, including the column padding glTF asks of small-component matrices.
std::uint64_t elementSize(int type, int componentType);
const char* typeName(int type);
const char* componentTypeName(int componentType);

// Checks accessor `index` (type, count, alignment, stride and that its data lies inside its
// buffer view, and a sparse accessor's indices and values inside theirs); reports at
// "/accessors/<index>". Buffer views must already be checked.
bool checkAccessor(const tinygltf::Model& model, int index, Reporter& report);

// The storage formats a vertex attribute may use: glTF 2.0 section 3.7.2.1, and the integer
// formats KHR_mesh_quantization adds. A bit set of them says what one attribute accepts.
enum AttributeFormat : unsigned {
    kFloat = 1u << 0,
    kUnorm8 = 1u << 1,  // normalized UNSIGNED_BYTE: c / 255
    kUnorm16 = 1u << 2, // normalized UNSIGNED_SHORT: c / 65535
    kSnorm8 = 1u << 3,  // normalized BYTE: max(c / 127, -1)
    kSnorm16 = 1u << 4, // normalized SHORT: max(c / 32767, -1)
    kUint8 = 1u << 5,   // UNSIGNED_BYTE as its integer value
    kSint8 = 1u << 6,   // BYTE
    kUint16 = 1u << 7,  // UNSIGNED_SHORT
    kSint16 = 1u << 8,  // SHORT
};

// Reads a float attribute with `components` components (1 = SCALAR, 2, 3, 4 = VEC2..4, 16 =
// MAT4, which only FLOAT stores without column padding) stored in one of the `formats` (a set of
// AttributeFormat bits), sparse accessors included. `usage` names the user in messages ("POSITION
// of /meshes/0/primitives/1"); `hint`, when not empty, is added to the refusal of a format outside
// `formats` (what would allow it).
bool readFloatAttribute(const tinygltf::Model& model, int index, int components, unsigned formats,
                        const std::string& usage, std::vector<float>& out, Reporter& report,
                        const std::string& hint = "");

// Reads a SCALAR UNSIGNED_BYTE/SHORT/INT index accessor.
bool readIndices(const tinygltf::Model& model, int index, const std::string& usage,
                 std::vector<std::uint32_t>& out, Reporter& report);

} // namespace rmsc::gltf
