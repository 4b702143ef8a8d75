// Accessor range checks and typed reads (see gltf_accessors.hpp).
#include "gltf_accessors.hpp"

#include <cmath>
#include <cstring>

namespace rmsc::gltf {

namespace {

std::string accessorPointer(int index) {
    return "/accessors/" + std::to_string(index);
}

// a * b + c without overflow; false when it does not fit 64 bits.
bool mulAdd(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t& out) {
    std::uint64_t product = 0;
    if (__builtin_mul_overflow(a, b, &product)) return false;
    return !__builtin_add_overflow(product, c, &out);
}

// The bytes of accessor `a`'s element `i`, or nullptr when it has no buffer view (all zeros).
struct ElementReader {
    const unsigned char* base = nullptr;
    std::uint64_t stride = 0;

    const unsigned char* at(std::uint64_t i) const { return base ? base + i * stride : nullptr; }
};

ElementReader elementReader(const tinygltf::Model& model, const tinygltf::Accessor& a) {
    ElementReader r;
    if (a.bufferView < 0) return r;
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
    const tinygltf::Buffer& buffer = model.buffers[std::size_t(view.buffer)];
    r.base = buffer.data.data() + view.byteOffset + a.byteOffset;
    r.stride = view.byteStride ? view.byteStride : elementSize(a.type, a.componentType);
    return r;
}

float readComponent(const unsigned char* p, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return float(*p) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return float(v) / 65535.0f;
    }
    default:
        return 0.0f;
    }
}

// Common refusals of a used accessor: sparse storage and over-large counts.
bool checkUsable(const tinygltf::Accessor& a, int index, std::uint64_t maxCount,
                 const std::string& usage, Reporter& report) {
    if (a.sparse.isSparse) {
        report.error(accessorPointer(index) + "/sparse",
                     "sparse accessors are not supported (used as " + usage + ")");
        return false;
    }
    if (a.count > maxCount) {
        report.error(accessorPointer(index), "count " + std::to_string(a.count) +
                                                 " is more than the limit of " +
                                                 std::to_string(maxCount));
        return false;
    }
    return true;
}

} // namespace

int componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    case TINYGLTF_TYPE_MAT2:
        return 4;
    case TINYGLTF_TYPE_MAT3:
        return 9;
    case TINYGLTF_TYPE_MAT4:
        return 16;
    default:
        return 0;
    }
}

std::uint64_t elementSize(int type, int componentType) {
    const std::uint64_t size = std::uint64_t(componentSize(componentType));
    // Matrix columns start on 4-byte boundaries.
    if (type == TINYGLTF_TYPE_MAT2 && size == 1) return 8;
    if (type == TINYGLTF_TYPE_MAT3 && size == 1) return 12;
    if (type == TINYGLTF_TYPE_MAT3 && size == 2) return 24;
    return size * std::uint64_t(componentCount(type));
}

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    default:
        return "unknown type";
    }
}

const char* componentTypeName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT:
        return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return "DOUBLE";
    default:
        return "unknown component type";
    }
}

bool checkAccessor(const tinygltf::Model& model, int index, Reporter& report) {
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    const std::string pointer = accessorPointer(index);
    const std::uint64_t cs = std::uint64_t(componentSize(a.componentType));
    if (cs == 0) {
        report.error(pointer + "/componentType",
                     std::string("component type ") + componentTypeName(a.componentType) +
                         " is not allowed in accessors, expected BYTE, UNSIGNED_BYTE, SHORT, "
                         "UNSIGNED_SHORT, UNSIGNED_INT or FLOAT");
        return false;
    }
    if (componentCount(a.type) == 0) {
        report.error(pointer + "/type", "unknown accessor type");
        return false;
    }
    if (a.count == 0) {
        report.error(pointer + "/count", "expected at least 1 element");
        return false;
    }
    if (a.bufferView < 0) return true; // all zeros (or sparse only)
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
    const std::string viewPointer = "/bufferViews/" + std::to_string(a.bufferView);
    const std::uint64_t element = elementSize(a.type, a.componentType);
    if (view.byteStride != 0) {
        if (view.byteStride < element) {
            report.error(pointer, "byteStride " + std::to_string(view.byteStride) + " of " +
                                      viewPointer + " is smaller than the " +
                                      std::to_string(element) + "-byte elements of this " +
                                      typeName(a.type) + " " + componentTypeName(a.componentType) +
                                      " accessor");
            return false;
        }
        if (view.byteStride % cs != 0) {
            report.error(pointer, "byteStride " + std::to_string(view.byteStride) + " of " +
                                      viewPointer + " is not a multiple of the component size " +
                                      std::to_string(cs));
            return false;
        }
    }
    if (a.byteOffset % cs != 0 || (view.byteOffset + a.byteOffset) % cs != 0) {
        report.error(pointer + "/byteOffset",
                     "data must start at a multiple of the component size " + std::to_string(cs) +
                         " in its buffer");
        return false;
    }
    const std::uint64_t stride = view.byteStride ? view.byteStride : element;
    std::uint64_t end = 0;
    if (!mulAdd(stride, std::uint64_t(a.count) - 1, element, end) ||
        __builtin_add_overflow(end, std::uint64_t(a.byteOffset), &end)) {
        report.error(pointer, "count " + std::to_string(a.count) + " with stride " +
                                  std::to_string(stride) + " overflows 64-bit byte offsets");
        return false;
    }
    if (end > view.byteLength) {
        report.error(pointer, "accessor needs bytes up to " + std::to_string(end) + " of " +
                                  viewPointer + ", which is only " +
                                  std::to_string(view.byteLength) + " bytes long");
        return false;
    }
    return true;
}

bool readFloatAttribute(const tinygltf::Model& model, int index, int components,
                        bool allowNormalized, const std::string& usage, std::vector<float>& out,
                        Reporter& report) {
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    const std::string pointer = accessorPointer(index);
    const int expectedType = components == 2   ? TINYGLTF_TYPE_VEC2
                             : components == 4 ? TINYGLTF_TYPE_VEC4
                                               : TINYGLTF_TYPE_VEC3;
    const bool isFloat = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool isNormalized =
        a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                         a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (a.type != expectedType || !(isFloat || (allowNormalized && isNormalized))) {
        report.error(pointer,
                     "used as " + usage + ": expected " + typeName(expectedType) +
                         (allowNormalized ? " FLOAT or normalized UNSIGNED_BYTE/SHORT" : " FLOAT") +
                         ", got " + typeName(a.type) + " " + componentTypeName(a.componentType) +
                         (a.normalized ? " (normalized)" : ""));
        return false;
    }
    if (!checkUsable(a, index, kMaxVertices, usage, report)) return false;
    const ElementReader reader = elementReader(model, a);
    const int cs = componentSize(a.componentType);
    out.assign(std::size_t(a.count) * std::size_t(components), 0.0f);
    if (!reader.base) return true;
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* element = reader.at(i);
        for (int c = 0; c < components; ++c) {
            const float v = readComponent(element + c * cs, a.componentType);
            if (!std::isfinite(v)) {
                report.error(pointer, "element " + std::to_string(i) + " (used as " + usage +
                                          ") is NaN or infinite, expected finite numbers");
                return false;
            }
            out[i * std::size_t(components) + std::size_t(c)] = v;
        }
    }
    return true;
}

bool readIndices(const tinygltf::Model& model, int index, const std::string& usage,
                 std::vector<std::uint32_t>& out, Reporter& report) {
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    const std::string pointer = accessorPointer(index);
    const int ct = a.componentType;
    if (a.type != TINYGLTF_TYPE_SCALAR ||
        !(ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
          ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
          ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) ||
        a.normalized) {
        report.error(pointer, "used as " + usage +
                                  ": expected SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or "
                                  "UNSIGNED_INT, got " +
                                  typeName(a.type) + " " + componentTypeName(ct) +
                                  (a.normalized ? " (normalized)" : ""));
        return false;
    }
    if (!checkUsable(a, index, kMaxIndices, usage, report)) return false;
    const ElementReader reader = elementReader(model, a);
    out.assign(a.count, 0u);
    if (!reader.base) return true;
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = reader.at(i);
        if (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
            out[i] = *p;
        } else if (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            out[i] = v;
        } else {
            std::memcpy(&out[i], p, 4);
        }
    }
    return true;
}

} // namespace rmsc::gltf
