// Reading and writing transforms in scene files, and the float-exact number writer.
#include "transform_json.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

namespace rmsc {
namespace {

// Float rounding of a normalization leaves |v|^2 within a few ulps of 1.
constexpr float kUnitTolerance = 1e-6f;

} // namespace

glm::vec3 normalizedForStorage(glm::vec3 v) {
    if (std::abs(glm::dot(v, v) - 1.0f) <= kUnitTolerance) return v;
    return glm::normalize(v);
}

glm::quat normalizedForStorage(glm::quat q) {
    if (std::abs(glm::dot(q, q) - 1.0f) <= kUnitTolerance) return q;
    return glm::normalize(q);
}

bool readTransform(const JsonReader& reader, const Json& object, const std::string& pointer,
                   Transform& transform) {
    bool ok = readVec3Field(reader, object, pointer, "position", &transform.position);
    const Json* rotation = findMember(object, "rotation");
    const Json* quaternion = findMember(object, "quaternion");
    if (rotation && quaternion) {
        reader.error(pointer, "give either \"rotation\" (Euler degrees) or \"quaternion\", not "
                              "both");
        ok = false;
    } else if (rotation) {
        if (const auto degrees = readVec3(reader, *rotation, childPointer(pointer, "rotation"))) {
            transform.rotation = eulerDegreesToQuaternion(*degrees);
        } else {
            ok = false;
        }
    } else if (quaternion) {
        const std::string quaternionPointer = childPointer(pointer, "quaternion");
        float xyzw[4];
        if (readNumbers(reader, *quaternion, quaternionPointer, 4, xyzw)) {
            const glm::quat q(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);
            if (glm::dot(q, q) > 0.0f) {
                transform.rotation = normalizedForStorage(q);
            } else {
                reader.error(quaternionPointer, "expected a non-zero quaternion [x, y, z, w]");
                ok = false;
            }
        } else {
            ok = false;
        }
    }
    if (const Json* scale = findMember(object, "scale")) {
        const std::string scalePointer = childPointer(pointer, "scale");
        NumberRange range = NumberRange::above(0.0);
        range.noun = "a scale";
        if (scale->is_array()) {
            if (const auto v = readVec3(reader, *scale, scalePointer, range)) {
                transform.scale = *v;
            } else {
                ok = false;
            }
        } else if (scale->is_number()) {
            if (const auto v = readNumber(reader, *scale, scalePointer, range)) {
                transform.scale = glm::vec3(*v);
            } else {
                ok = false;
            }
        } else {
            reader.error(scalePointer, "expected a scale > 0 (a number, or [x, y, z]), got " +
                                           jsonTypeName(*scale));
            ok = false;
        }
    }
    return ok;
}

void writeTransform(const Transform& transform, Json& object) {
    if (transform.position != glm::vec3(0.0f)) object["position"] = vec3ToJson(transform.position);
    const glm::quat& q = transform.rotation;
    if (q != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        if (const std::optional<glm::vec3> degrees = exactEulerDegrees(q)) {
            object["rotation"] = vec3ToJson(*degrees);
        } else {
            object["quaternion"] = Json::array(
                {floatToJson(q.x), floatToJson(q.y), floatToJson(q.z), floatToJson(q.w)});
        }
    }
    const glm::vec3& s = transform.scale;
    if (s != glm::vec3(1.0f)) {
        object["scale"] = s.x == s.y && s.y == s.z ? floatToJson(s.x) : vec3ToJson(s);
    }
}

Json floatToJson(float value) {
    if (std::isnan(value)) value = 0.0f;
    value =
        std::clamp(value, -std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
    // The shortest decimal that reads back as this float, stored as the double nearest to it,
    // which nlohmann writes with the same digits.
    char buffer[64];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    double shortest = 0.0;
    std::from_chars(buffer, written.ptr, shortest);
    if (shortest == std::floor(shortest) && std::abs(shortest) < 1e15)
        return Json(std::int64_t(shortest)); // "1", not "1.0"
    return Json(shortest);
}

Json vec3ToJson(glm::vec3 v) {
    return Json::array({floatToJson(v.x), floatToJson(v.y), floatToJson(v.z)});
}

} // namespace rmsc
