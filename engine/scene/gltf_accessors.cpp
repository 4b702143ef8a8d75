// Accessor range checks and typed reads (see gltf_accessors.hpp).
#include "gltf_accessors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

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

// The AttributeFormat of an accessor's (componentType, normalized), 0 when none.
unsigned formatOf(const tinygltf::Accessor& a) {
    switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return a.normalized ? 0u : kFloat;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return a.normalized ? kUnorm8 : kUint8;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return a.normalized ? kUnorm16 : kUint16;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return a.normalized ? kSnorm8 : kSint8;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return a.normalized ? kSnorm16 : kSint16;
    default:
        return 0u;
    }
}

std::string formatNames(unsigned formats) {
    static const std::pair<unsigned, const char*> kNames[] = {
        {kFloat, "FLOAT"},
        {kUnorm8, "normalized UNSIGNED_BYTE"},
        {kUnorm16, "normalized UNSIGNED_SHORT"},
        {kSnorm8, "normalized BYTE"},
        {kSnorm16, "normalized SHORT"},
        {kUint8, "UNSIGNED_BYTE"},
        {kSint8, "BYTE"},
        {kUint16, "UNSIGNED_SHORT"},
        {kSint16, "SHORT"}};
    std::string out;
    for (const auto& [bit, name] : kNames)
        if (formats & bit) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

// One component in `format` as a float. Normalized integers as glTF 2.0 section 3.11 says.
float readComponent(const unsigned char* p, unsigned format) {
    switch (format) {
    case kFloat: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case kUnorm8:
        return float(*p) / 255.0f;
    case kUint8:
        return float(*p);
    case kSnorm8:
        return std::max(float(std::int8_t(*p)) / 127.0f, -1.0f);
    case kSint8:
        return float(std::int8_t(*p));
    case kUnorm16:
    case kUint16: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return format == kUnorm16 ? float(v) / 65535.0f : float(v);
    }
    case kSnorm16:
    case kSint16: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return format == kSnorm16 ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    default:
        return 0.0f;
    }
}

std::uint32_t readIndexValue(const unsigned char* p, int componentType) {
    if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return *p;
    if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

// A sparse accessor's substitutions (glTF 2.0 section 3.6.2.3): which element each replaces
// and where its value's bytes are. Ranges were checked by checkAccessor; what is left is that
// the indices increase strictly and stay below the accessor's count.
bool sparseEntries(const tinygltf::Model& model, const tinygltf::Accessor& a, int index,
                   const std::string& usage,
                   std::vector<std::pair<std::uint32_t, const unsigned char*>>& entries,
                   Reporter& report) {
    entries.clear();
    if (!a.sparse.isSparse) return true;
    const auto bytesOf = [&](int viewIndex, std::uint64_t offset) {
        const tinygltf::BufferView& view = model.bufferViews[std::size_t(viewIndex)];
        return model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + offset;
    };
    const unsigned char* indices =
        bytesOf(a.sparse.indices.bufferView, std::uint64_t(a.sparse.indices.byteOffset));
    const unsigned char* values =
        bytesOf(a.sparse.values.bufferView, std::uint64_t(a.sparse.values.byteOffset));
    const std::uint64_t indexSize = std::uint64_t(componentSize(a.sparse.indices.componentType));
    const std::uint64_t valueSize = elementSize(a.type, a.componentType);
    entries.reserve(std::size_t(a.sparse.count));
    for (std::uint64_t i = 0; i < std::uint64_t(a.sparse.count); ++i) {
        const std::uint32_t target =
            readIndexValue(indices + i * indexSize, a.sparse.indices.componentType);
        if (target >= a.count || (!entries.empty() && target <= entries.back().first)) {
            report.error(accessorPointer(index) + "/sparse/indices",
                         "index " + std::to_string(target) + " at element " + std::to_string(i) +
                             " (used as " + usage + ") is " +
                             (target >= a.count
                                  ? "not less than the accessor's count " + std::to_string(a.count)
                                  : std::string("not greater than the one before")) +
                             ", expected strictly increasing element indices");
            return false;
        }
        entries.emplace_back(target, values + i * valueSize);
    }
    return true;
}

// Common refusal of a used accessor: over-large counts.
bool checkUsable(const tinygltf::Accessor& a, int index, std::uint64_t maxCount, Reporter& report) {
    if (a.count > maxCount) {
        report.error(accessorPointer(index), "count " + std::to_string(a.count) +
                                                 " is more than the limit of " +
                                                 std::to_string(maxCount));
        return false;
    }
    return true;
}

// Checks the sparse storage of accessor `index`: its count, index type and that its indices
// and values lie inside their buffer views.
bool checkSparse(const tinygltf::Model& model, int index, Reporter& report) {
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    const std::string pointer = accessorPointer(index) + "/sparse";
    if (a.sparse.count < 1 || std::uint64_t(a.sparse.count) > std::uint64_t(a.count)) {
        report.error(pointer + "/count", "expected from 1 to the accessor's count " +
                                             std::to_string(a.count) + ", got " +
                                             std::to_string(a.sparse.count));
        return false;
    }
    const int it = a.sparse.indices.componentType;
    if (it != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        it != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        it != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        report.error(pointer + "/indices/componentType",
                     "expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got " +
                         std::string(componentTypeName(it)));
        return false;
    }
    const auto inside = [&](const char* what, int viewIndex, int offset, std::uint64_t size,
                            std::uint64_t alignment) {
        const std::string p = pointer + "/" + what;
        if (viewIndex < 0 || std::size_t(viewIndex) >= model.bufferViews.size()) {
            report.error(p + "/bufferView", "refers to a buffer view that does not exist");
            return false;
        }
        const tinygltf::BufferView& view = model.bufferViews[std::size_t(viewIndex)];
        if (offset < 0 || (view.byteOffset + std::uint64_t(offset)) % alignment != 0) {
            report.error(p + "/byteOffset", "data must start at a multiple of the component size " +
                                                std::to_string(alignment) + " in its buffer");
            return false;
        }
        std::uint64_t end = 0;
        if (!mulAdd(size, std::uint64_t(a.sparse.count), std::uint64_t(offset), end) ||
            end > view.byteLength) {
            report.error(p, std::to_string(a.sparse.count) + " " + what + " of " +
                                std::to_string(size) + " bytes from byte " +
                                std::to_string(offset) + " do not fit /bufferViews/" +
                                std::to_string(viewIndex) + " (" + std::to_string(view.byteLength) +
                                " bytes)");
            return false;
        }
        return true;
    };
    const std::uint64_t indexSize = std::uint64_t(componentSize(it));
    return inside("indices", a.sparse.indices.bufferView, a.sparse.indices.byteOffset, indexSize,
                  indexSize) &&
           inside("values", a.sparse.values.bufferView, a.sparse.values.byteOffset,
                  elementSize(a.type, a.componentType),
                  std::uint64_t(componentSize(a.componentType)));
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
    if (a.sparse.isSparse && !checkSparse(model, index, report)) return false;
    if (a.bufferView < 0) return true; // all zeros (and the sparse values)
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

bool readFloatAttribute(const tinygltf::Model& model, int index, int components, unsigned formats,
                        const std::string& usage, std::vector<float>& out, Reporter& report,
                        const std::string& hint) {
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    const std::string pointer = accessorPointer(index);
    const int expectedType = components == 1    ? TINYGLTF_TYPE_SCALAR
                             : components == 2  ? TINYGLTF_TYPE_VEC2
                             : components == 4  ? TINYGLTF_TYPE_VEC4
                             : components == 16 ? TINYGLTF_TYPE_MAT4
                                                : TINYGLTF_TYPE_VEC3;
    const unsigned format = formatOf(a);
    if (a.type != expectedType || (format & formats) == 0) {
        report.error(pointer, "used as " + usage + ": expected " + typeName(expectedType) + " " +
                                  formatNames(formats) + ", got " + typeName(a.type) + " " +
                                  componentTypeName(a.componentType) +
                                  (a.normalized ? " (normalized)" : "") +
                                  (a.type == expectedType && !hint.empty() ? "; " + hint : ""));
        return false;
    }
    if (!checkUsable(a, index, kMaxVertices, report)) return false;
    std::vector<std::pair<std::uint32_t, const unsigned char*>> sparse;
    if (!sparseEntries(model, a, index, usage, sparse, report)) return false;
    const ElementReader reader = elementReader(model, a);
    const int cs = componentSize(a.componentType);
    out.assign(std::size_t(a.count) * std::size_t(components), 0.0f);
    const auto readElement = [&](std::size_t i, const unsigned char* element) {
        for (int c = 0; c < components; ++c) {
            const float v = readComponent(element + c * cs, format);
            if (!std::isfinite(v)) {
                report.error(pointer, "element " + std::to_string(i) + " (used as " + usage +
                                          ") is NaN or infinite, expected finite numbers");
                return false;
            }
            out[i * std::size_t(components) + std::size_t(c)] = v;
        }
        return true;
    };
    if (reader.base)
        for (std::size_t i = 0; i < a.count; ++i)
            if (!readElement(i, reader.at(i))) return false;
    for (const auto& [target, bytes] : sparse)
        if (!readElement(target, bytes)) return false;
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
    if (!checkUsable(a, index, kMaxIndices, report)) return false;
    std::vector<std::pair<std::uint32_t, const unsigned char*>> sparse;
    if (!sparseEntries(model, a, index, usage, sparse, report)) return false;
    const ElementReader reader = elementReader(model, a);
    out.assign(a.count, 0u);
    if (reader.base)
        for (std::size_t i = 0; i < a.count; ++i)
            out[i] = readIndexValue(reader.at(i), ct);
    for (const auto& [target, bytes] : sparse)
        out[target] = readIndexValue(bytes, ct);
    return true;
}

} // namespace rmsc::gltf
