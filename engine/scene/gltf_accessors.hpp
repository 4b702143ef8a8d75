// glTF accessors: element sizes, the overflow-checked range check of an accessor against its
// buffer view, and typed reads of vertex attributes and indices that refuse unexpected types,
// sparse accessors and non-finite values.
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
// buffer view); reports at "/accessors/<index>". Buffer views must already be checked.
bool checkAccessor(const tinygltf::Model& model, int index, Reporter& report);

// Reads a float attribute with `components` components (2 or 3). Accepts FLOAT data, and
// normalized UNSIGNED_BYTE / UNSIGNED_SHORT where `allowNormalized`. `usage` names the user in
// messages ("POSITION of /meshes/0/primitives/1").
bool readFloatAttribute(const tinygltf::Model& model, int index, int components,
                        bool allowNormalized, const std::string& usage, std::vector<float>& out,
                        Reporter& report);

// Reads a SCALAR UNSIGNED_BYTE/SHORT/INT index accessor.
bool readIndices(const tinygltf::Model& model, int index, const std::string& usage,
                 std::vector<std::uint32_t>& out, Reporter& report);

} // namespace rmsc::gltf
