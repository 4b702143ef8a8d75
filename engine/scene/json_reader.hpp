// Typed reading of JSON values for the scene reader: each function checks one value's type and
// range and, if it is wrong, reports an error at the value's JSON pointer and returns nothing,
// so a reader can check every field of a file in one pass. Also JSON pointers, unknown-key
// warnings with "did you mean" suggestions, and the parse step that catches what nlohmann
// accepts silently (duplicate keys, non-finite numbers, unbounded nesting).
#pragma once

#include "core/diagnostics.hpp"
#include "core/limits.hpp"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc {

using Json = nlohmann::ordered_json;

constexpr int kMaxJsonDepth =
    limits::kSceneJsonDepth; // arrays and objects nested deeper than this are refused

// Where diagnostics for one file go.
struct JsonReader {
    std::string file;
    Diagnostics* diagnostics = nullptr;

    void error(const std::string& pointer, std::string message) const;
    void warning(const std::string& pointer, std::string message) const;
};

// Parses JSON text. Syntax errors ("line 3, column 14"), numbers too large to represent (1e999,
// at the number's pointer) and nesting deeper than kMaxJsonDepth return nullopt. Duplicate keys
// are reported at their pointers but the document is still returned, so the caller can go on
// checking it.
std::optional<Json> parseJsonText(std::string_view text, const JsonReader& reader);

// "/a/b" + "c~d" -> "/a/b/c~0d" (RFC 6901 escaping); "/a" + 3 -> "/a/3".
std::string childPointer(std::string_view parent, std::string_view key);
std::string childPointer(std::string_view parent, std::size_t index);

// "a string", "an array", "a number", ... for "expected X, got Y" messages.
std::string jsonTypeName(const Json& value);
// The shortest text that reads back as the same float (or double): 0.1f -> "0.1".
std::string formatNumber(float value);
std::string formatNumber(double value);
// Quoted, comma-separated: "\"a\", \"b\"". Lists longer than kQuotedNames end with
// " and N more" (a scene may define thousands of materials).
constexpr std::size_t kQuotedNames = 64;
std::string quotedList(std::span<const std::string> names);

// Edit distance: insertions, deletions, substitutions and swaps of neighbouring letters.
int editDistance(std::string_view a, std::string_view b);
// `candidates` sorted by edit distance to `name`, nearest first (ties keep their order).
std::vector<std::string> sortedByDistance(std::string_view name,
                                          std::span<const std::string> candidates);
// The candidate close enough to `name` to be a likely typo, or nullopt.
std::optional<std::string> closeMatch(std::string_view name,
                                      std::span<const std::string> candidates);

// Warns about every key of `object` not in `known`, suggesting the nearest known key.
void warnUnknownKeys(const JsonReader& reader, const Json& object, const std::string& pointer,
                     std::span<const std::string> known);
// The member `key` of `object`, or nullptr when absent.
const Json* findMember(const Json& object, std::string_view key);

// Reports an error unless `value` is an object.
bool expectObject(const JsonReader& reader, const Json& value, const std::string& pointer);

// Allowed values of a number, for checking and for messages ("expected a number in [0, 1]").
struct NumberRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minExclusive = false;
    bool maxExclusive = false;
    const char* noun = "a number"; // what the value is called in messages

    static NumberRange any() { return {}; }
    static NumberRange atLeast(double lo) { return {lo, any().max, false, false}; }
    static NumberRange above(double lo) { return {lo, any().max, true, false}; }
    static NumberRange closed(double lo, double hi) { return {lo, hi, false, false}; }
    static NumberRange open(double lo, double hi) { return {lo, hi, true, true}; }
    static NumberRange openClosed(double lo, double hi) { return {lo, hi, true, false}; }

    bool contains(double v) const;
    std::string describe() const; // "a number > 0", "a number in (0, 180)"
};

// A finite number representable as a float, within `range`.
std::optional<float> readNumber(const JsonReader& reader, const Json& value,
                                const std::string& pointer, NumberRange range = {});
// An integer (written without a fraction, or with a zero one) in [lo, hi].
std::optional<int> readInteger(const JsonReader& reader, const Json& value,
                               const std::string& pointer, int lo, int hi);
// An array of exactly `count` numbers, each within `range`; errors point at the elements.
bool readNumbers(const JsonReader& reader, const Json& value, const std::string& pointer, int count,
                 float* out, NumberRange range = {});
std::optional<glm::vec3> readVec3(const JsonReader& reader, const Json& value,
                                  const std::string& pointer, NumberRange range = {});
std::optional<std::string> readString(const JsonReader& reader, const Json& value,
                                      const std::string& pointer);
// A linear colour [r, g, b] with components >= 0, or "#rrggbb" in sRGB (converted to linear).
std::optional<glm::vec3> readColor(const JsonReader& reader, const Json& value,
                                   const std::string& pointer);

// Field forms: read object[key] into *out if present. Absent leaves *out as it is (the default)
// and returns true; present but invalid reports an error and returns false.
bool readNumberField(const JsonReader& reader, const Json& object, const std::string& pointer,
                     std::string_view key, float* out, NumberRange range = {});
bool readIntegerField(const JsonReader& reader, const Json& object, const std::string& pointer,
                      std::string_view key, int* out, int lo, int hi);
bool readVec3Field(const JsonReader& reader, const Json& object, const std::string& pointer,
                   std::string_view key, glm::vec3* out, NumberRange range = {});
bool readStringField(const JsonReader& reader, const Json& object, const std::string& pointer,
                     std::string_view key, std::string* out);
bool readColorField(const JsonReader& reader, const Json& object, const std::string& pointer,
                    std::string_view key, glm::vec3* out);

} // namespace rmsc
