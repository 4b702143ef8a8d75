// The "position", "rotation" / "quaternion" and "scale" keys that place mesh instances and SDF
// nodes, read and written, and the Euler-angle convention of the scene format.
#pragma once

#include "json_reader.hpp"
#include "scene/scene.hpp"

#include <string>

namespace rmsc {

// `v` scaled to unit length; a vector already unit length to within float rounding is returned
// unchanged, so normalizing on every load keeps values that were saved exactly as they were.
glm::vec3 normalizedForStorage(glm::vec3 v);
glm::quat normalizedForStorage(glm::quat q);

// Reads the transform keys of `object` into `transform` (absent keys keep its values).
// Returns false if any was present but invalid (reported).
bool readTransform(const JsonReader& reader, const Json& object, const std::string& pointer,
                   Transform& transform);

// Writes the transform keys that differ from the identity: "position", "rotation" (Euler
// degrees, where short ones read back exactly: exactEulerDegrees) or else "quaternion"
// [x, y, z, w] (exact), "scale" (a number when uniform).
void writeTransform(const Transform& transform, Json& object);

// A float as a JSON number that reads back as exactly the same float, written in the fewest
// digits (0.1f as 0.1). Non-finite values are clamped (NaN to 0, infinities to the largest
// float) so the output is always valid, finite JSON.
Json floatToJson(float value);
Json vec3ToJson(glm::vec3 v);

} // namespace rmsc
