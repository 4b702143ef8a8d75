// Catalogue parameters as JSON (param_json.hpp). The messages are those of the typed readers
// of json_reader.hpp, plus the spec's description where a key is missing.
#include "param_json.hpp"

#include "sdf/profiles.hpp"
#include "transform_json.hpp"

#include <cassert>

namespace rmsc {
namespace {

// The member `spec.key` of `object`; nullptr when absent, with an error when it is required.
const Json* member(const JsonReader& reader, const Json& object, const std::string& pointer,
                   const SdfParamSpec& spec, bool& ok) {
    const Json* value = findMember(object, spec.key);
    ok = value || !spec.required;
    if (!ok)
        reader.error(pointer, "missing \"" + std::string(spec.key) + "\" (" +
                                  std::string(spec.description) + ")");
    return value;
}

std::string keyPointer(const std::string& pointer, const SdfParamSpec& spec) {
    return childPointer(pointer, spec.key);
}

// "x", "y" or "z" to 0, 1, 2.
std::optional<int> readAxisName(const JsonReader& reader, const Json& value,
                                const std::string& pointer) {
    const auto name = readString(reader, value, pointer);
    if (!name) return std::nullopt;
    if (*name == "x") return 0;
    if (*name == "y") return 1;
    if (*name == "z") return 2;
    reader.error(pointer, "expected an axis \"x\", \"y\" or \"z\", got \"" + *name + "\"");
    return std::nullopt;
}

} // namespace

NumberRange numberRange(const ParamRange& range) {
    return {range.min, range.max, range.minExclusive, range.maxExclusive};
}

NumberRange numberRange(const SdfParamSpec& spec) {
    NumberRange range = numberRange(spec.range);
    if (!spec.noun.empty()) range.noun = spec.noun.data(); // string literals: NUL-terminated
    return range;
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, float& out) {
    assert(spec.type == ParamType::Number);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    const auto v = readNumber(reader, *value, keyPointer(pointer, spec), numberRange(spec));
    if (v) out = *v;
    return v.has_value();
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, int& out) {
    assert(spec.type == ParamType::Integer || spec.type == ParamType::Axis);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    const std::optional<int> v = spec.type == ParamType::Axis
                                     ? readAxisName(reader, *value, keyPointer(pointer, spec))
                                     : readInteger(reader, *value, keyPointer(pointer, spec),
                                                   int(spec.range.min), int(spec.range.max));
    if (v) out = *v;
    return v.has_value();
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::vec2& out) {
    assert(spec.type == ParamType::Vec2);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    float v[2];
    if (!readNumbers(reader, *value, keyPointer(pointer, spec), 2, v, numberRange(spec)))
        return false;
    out = glm::vec2(v[0], v[1]);
    return true;
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::vec3& out) {
    assert(spec.type == ParamType::Vec3);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    float v[3];
    if (!readNumbers(reader, *value, keyPointer(pointer, spec), 3, v, numberRange(spec)))
        return false;
    out = glm::vec3(v[0], v[1], v[2]);
    return true;
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::ivec3& out) {
    assert(spec.type == ParamType::IVec3);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    const std::string valuePointer = keyPointer(pointer, spec);
    if (!value->is_array() || value->size() != 3) {
        reader.error(
            valuePointer,
            "expected 3 integers (" + std::string(spec.description) + "), got " +
                jsonTypeName(*value) +
                (value->is_array() ? " of " + std::to_string(value->size()) + " elements" : ""));
        return false;
    }
    for (int axis = 0; axis < 3; ++axis) {
        const auto n = readInteger(reader, (*value)[std::size_t(axis)],
                                   childPointer(valuePointer, std::size_t(axis)),
                                   int(spec.range.min), int(spec.range.max));
        if (n) {
            out[axis] = *n;
        } else {
            ok = false;
        }
    }
    return ok;
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, bool& out) {
    assert(spec.type == ParamType::Bool);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    if (!value->is_boolean()) {
        reader.error(keyPointer(pointer, spec),
                     "expected true or false, got " + jsonTypeName(*value));
        return false;
    }
    out = value->get<bool>();
    return true;
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::bvec3& out) {
    assert(spec.type == ParamType::Axes);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    const std::string valuePointer = keyPointer(pointer, spec);
    const auto text = readString(reader, *value, valuePointer);
    if (!text) return false;
    ok = !text->empty();
    for (char c : *text) {
        const int axis = c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1;
        if (axis < 0 || out[axis]) ok = false;
        if (axis >= 0) out[axis] = true;
    }
    if (!ok)
        reader.error(valuePointer, "expected one to three different axes among \"x\", \"y\", "
                                   "\"z\" (e.g. \"xz\"), got \"" +
                                       *text + "\"");
    return ok;
}

bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, std::vector<glm::vec2>& out) {
    assert(spec.type == ParamType::Points);
    bool ok = true;
    const Json* value = member(reader, object, pointer, spec, ok);
    if (!value) return ok;
    const std::string valuePointer = keyPointer(pointer, spec);
    if (!value->is_array()) {
        reader.error(valuePointer,
                     "expected an array of [x, y] points, got " + jsonTypeName(*value));
        return false;
    }
    if (value->size() < std::size_t(kMinPolygonPoints) ||
        value->size() > std::size_t(kMaxPolygonPoints)) {
        reader.error(valuePointer, "a polygon needs " + std::to_string(kMinPolygonPoints) + " to " +
                                       std::to_string(kMaxPolygonPoints) + " points, got " +
                                       std::to_string(value->size()));
        return false;
    }
    out.clear();
    for (std::size_t i = 0; i < value->size(); ++i) {
        float v[2];
        if (readNumbers(reader, (*value)[i], childPointer(valuePointer, i), 2, v,
                        numberRange(spec))) {
            out.emplace_back(v[0], v[1]);
        } else {
            ok = false;
        }
    }
    return ok;
}

void setDefault(const SdfParamSpec& spec, float& out) {
    out = spec.value[0];
}
void setDefault(const SdfParamSpec& spec, int& out) {
    out = int(spec.value[0]);
}
void setDefault(const SdfParamSpec& spec, glm::vec2& out) {
    out = glm::vec2(spec.value[0], spec.value[1]);
}
void setDefault(const SdfParamSpec& spec, glm::vec3& out) {
    out = glm::vec3(spec.value[0], spec.value[1], spec.value[2]);
}
void setDefault(const SdfParamSpec& spec, glm::ivec3& out) {
    out = glm::ivec3(glm::vec3(spec.value[0], spec.value[1], spec.value[2]));
}
void setDefault(const SdfParamSpec& spec, bool& out) {
    out = spec.value[0] != 0.0f;
}
void setDefault(const SdfParamSpec& spec, glm::bvec3& out) {
    out = glm::bvec3(spec.value[0] != 0.0f, spec.value[1] != 0.0f, spec.value[2] != 0.0f);
}
void setDefault(const SdfParamSpec&, std::vector<glm::vec2>& out) {
    out.clear();
}

Json paramToJson(const SdfParamSpec&, float value) {
    return floatToJson(value);
}
Json paramToJson(const SdfParamSpec& spec, int value) {
    if (spec.type == ParamType::Axis) return std::string(1, "xyz"[std::clamp(value, 0, 2)]);
    return value;
}
Json paramToJson(const SdfParamSpec&, glm::vec2 value) {
    return Json::array({floatToJson(value.x), floatToJson(value.y)});
}
Json paramToJson(const SdfParamSpec&, glm::vec3 value) {
    return vec3ToJson(value);
}
Json paramToJson(const SdfParamSpec&, glm::ivec3 value) {
    return Json::array({value.x, value.y, value.z});
}
Json paramToJson(const SdfParamSpec&, bool value) {
    return value;
}
Json paramToJson(const SdfParamSpec&, glm::bvec3 value) {
    std::string axes;
    for (int axis = 0; axis < 3; ++axis)
        if (value[axis]) axes += "xyz"[axis];
    return axes;
}
Json paramToJson(const SdfParamSpec& spec, const std::vector<glm::vec2>& value) {
    Json points = Json::array();
    for (const glm::vec2& point : value)
        points.push_back(paramToJson(spec, point));
    return points;
}

Json paramDefaultToJson(const SdfParamSpec& spec) {
    const auto as = [&](auto value) {
        setDefault(spec, value);
        return paramToJson(spec, value);
    };
    switch (spec.type) {
    case ParamType::Number:
        return as(0.0f);
    case ParamType::Integer:
    case ParamType::Axis:
        return as(0);
    case ParamType::Vec2:
        return as(glm::vec2());
    case ParamType::Vec3:
        return as(glm::vec3());
    case ParamType::IVec3:
        return as(glm::ivec3());
    case ParamType::Bool:
        return as(false);
    case ParamType::Axes:
        return as(glm::bvec3());
    case ParamType::Points:
        return as(std::vector<glm::vec2>());
    }
    return Json();
}

} // namespace rmsc
