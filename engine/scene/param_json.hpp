// Reading and writing the parameters of catalogue rows (sdf/param_spec.hpp: the keys of
// modifiers, profiles and profile solids) by their spec: the JSON type, the range, the
// "missing" message and whether the writer leaves a default out all come from the row.
#pragma once

#include "json_reader.hpp"
#include "sdf/param_spec.hpp"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace rmsc {

// The reader's NumberRange for a spec's range, with the spec's noun.
NumberRange numberRange(const SdfParamSpec& spec);
// The reader's NumberRange for a range ("a number" in messages).
NumberRange numberRange(const ParamRange& range);

// Reads `spec.key` of `object` (at `pointer`) into `out`. Absent: an error when the parameter is
// required, else `out` is left as it is (the default). Returns false on any error. The type of
// `out` must be the one ParamType stores in: float (Number), int (Integer, Axis), glm::vec2,
// glm::vec3, glm::ivec3, bool, glm::bvec3 (Axes), std::vector<glm::vec2> (Points).
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, float& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, int& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::vec2& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::vec3& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::ivec3& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, bool& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, glm::bvec3& out);
bool readParam(const JsonReader& reader, const Json& object, const std::string& pointer,
               const SdfParamSpec& spec, std::vector<glm::vec2>& out);

// Sets `out` to the spec's default.
void setDefault(const SdfParamSpec& spec, float& out);
void setDefault(const SdfParamSpec& spec, int& out);
void setDefault(const SdfParamSpec& spec, glm::vec2& out);
void setDefault(const SdfParamSpec& spec, glm::vec3& out);
void setDefault(const SdfParamSpec& spec, glm::ivec3& out);
void setDefault(const SdfParamSpec& spec, bool& out);
void setDefault(const SdfParamSpec& spec, glm::bvec3& out);
void setDefault(const SdfParamSpec& spec, std::vector<glm::vec2>& out);

// The spec's default as the writer writes it.
Json paramDefaultToJson(const SdfParamSpec& spec);

// Writes `value` as `spec.key` of `object`, unless the spec leaves the default out and `value`
// is the default.
template <typename T> void writeParam(const SdfParamSpec& spec, const T& value, Json& object);

Json paramToJson(const SdfParamSpec& spec, float value);
Json paramToJson(const SdfParamSpec& spec, int value);
Json paramToJson(const SdfParamSpec& spec, glm::vec2 value);
Json paramToJson(const SdfParamSpec& spec, glm::vec3 value);
Json paramToJson(const SdfParamSpec& spec, glm::ivec3 value);
Json paramToJson(const SdfParamSpec& spec, bool value);
Json paramToJson(const SdfParamSpec& spec, glm::bvec3 value);
Json paramToJson(const SdfParamSpec& spec, const std::vector<glm::vec2>& value);

template <typename T> void writeParam(const SdfParamSpec& spec, const T& value, Json& object) {
    if (!spec.writtenAtDefault) {
        T fallback{};
        setDefault(spec, fallback);
        if (value == fallback) return;
    }
    object[std::string(spec.key)] = paramToJson(spec, value);
}

} // namespace rmsc
