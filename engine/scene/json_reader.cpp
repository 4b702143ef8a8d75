// Typed JSON value readers with JSON-pointer diagnostics, and the name-suggestion helpers used
// by the scene reader's messages.
#include "json_reader.hpp"

#include "core/number_text.hpp"
#include "core/srgb.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {

void JsonReader::error(const std::string& pointer, std::string message) const {
    diagnostics->error(file, pointer, std::move(message));
}

void JsonReader::warning(const std::string& pointer, std::string message) const {
    diagnostics->warning(file, pointer, std::move(message));
}

std::string childPointer(std::string_view parent, std::string_view key) {
    std::string out(parent);
    out += '/';
    for (char c : key) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

std::string childPointer(std::string_view parent, std::size_t index) {
    return std::string(parent) + "/" + std::to_string(index);
}

std::string jsonTypeName(const Json& value) {
    switch (value.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "a number";
    case Json::value_t::string:
        return "a string";
    case Json::value_t::array:
        return "an array";
    case Json::value_t::object:
        return "an object";
    default:
        return "an unsupported value";
    }
}

std::string formatNumber(float value) {
    return shortestNumberText(value);
}

std::string formatNumber(double value) {
    return shortestNumberText(value);
}

std::string quotedList(std::span<const std::string> names) {
    std::string out;
    const std::size_t shown = std::min(names.size(), kQuotedNames);
    for (std::size_t i = 0; i < shown; ++i) {
        if (!out.empty()) out += ", ";
        out += "\"" + names[i] + "\"";
    }
    if (shown < names.size()) out += " and " + std::to_string(names.size() - shown) + " more";
    return out;
}

namespace {

// Optimal string alignment: Levenshtein plus swaps of neighbouring letters ("rde" -> "red"),
// the most common typo. Rows i - 2, i - 1 and i of the table (d[i][j] is the distance between
// a's first i and b's first j letters) live in `rows`, reused between calls.
int editDistance(std::string_view a, std::string_view b, std::vector<int>& rows) {
    const std::size_t columns = b.size() + 1;
    rows.assign(3 * columns, 0);
    auto at = [&](std::size_t i, std::size_t j) -> int& { return rows[(i % 3) * columns + j]; };
    for (std::size_t j = 0; j <= b.size(); ++j)
        at(0, j) = int(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        at(i, 0) = int(i);
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
        }
    }
    return at(a.size(), b.size());
}

// Names longer than this are not ranked against a list (no short name is a likely typo of
// them, and ranking would cost their length times every candidate's).
constexpr std::size_t kRankedNameLength = 256;

} // namespace

int editDistance(std::string_view a, std::string_view b) {
    std::vector<int> rows;
    return editDistance(a, b, rows);
}

std::vector<std::string> sortedByDistance(std::string_view name,
                                          std::span<const std::string> candidates) {
    if (name.size() > kRankedNameLength)
        return std::vector<std::string>(candidates.begin(), candidates.end());
    // Each distance once (a comparison sort would compute them n log n times).
    std::vector<std::pair<int, std::size_t>> ranked;
    std::vector<int> rows;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        ranked.emplace_back(editDistance(name, candidates[i], rows), i);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::string> sorted;
    sorted.reserve(ranked.size());
    for (const auto& [distance, index] : ranked)
        sorted.push_back(candidates[index]);
    return sorted;
}

std::optional<std::string> closeMatch(std::string_view name,
                                      std::span<const std::string> candidates) {
    // A typo changes a few letters; more than a third of the name is a different word.
    const int allowed = std::max<int>(1, int(std::max(name.size(), std::size_t(3))) / 3);
    std::optional<std::string> best;
    int bestDistance = 0;
    std::vector<int> rows;
    for (const std::string& candidate : candidates) {
        // The distance is at least the difference in length: skip what cannot be close.
        const std::size_t longer = std::max(name.size(), candidate.size());
        const std::size_t shorter = std::min(name.size(), candidate.size());
        if (longer - shorter > std::size_t(allowed)) continue;
        const int d = editDistance(name, candidate, rows);
        if (d <= allowed && (!best || d < bestDistance)) {
            best = candidate;
            bestDistance = d;
        }
    }
    return best;
}

void warnUnknownKeys(const JsonReader& reader, const Json& object, const std::string& pointer,
                     std::span<const std::string> known) {
    if (!object.is_object()) return;
    for (const auto& [key, value] : object.items()) {
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        if (!reader.diagnostics->keeps()) { // counted, but not kept: no message to build
            reader.warning(pointer, "unknown key");
            continue;
        }
        std::string message = "unknown key \"" + key + "\"";
        if (auto match = closeMatch(key, known)) {
            message += "; did you mean \"" + *match + "\"?";
        } else {
            message += " (ignored); known keys: " + quotedList(known);
        }
        reader.warning(childPointer(pointer, key), message);
    }
}

const Json* findMember(const Json& object, std::string_view key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

bool expectObject(const JsonReader& reader, const Json& value, const std::string& pointer) {
    if (value.is_object()) return true;
    reader.error(pointer, "expected an object, got " + jsonTypeName(value));
    return false;
}

bool NumberRange::contains(double v) const {
    const bool aboveMin = minExclusive ? v > min : v >= min;
    const bool belowMax = maxExclusive ? v < max : v <= max;
    return aboveMin && belowMax;
}

namespace {

// Bounds often come from float tables (1e-4f): print those as the float they are.
std::string boundText(double bound) {
    const float asFloat = float(bound);
    return double(asFloat) == bound ? formatNumber(asFloat) : formatNumber(bound);
}

} // namespace

std::string NumberRange::describe() const {
    const bool hasMin = std::isfinite(min);
    const bool hasMax = std::isfinite(max);
    std::string out = noun;
    if (hasMin && hasMax) {
        out += std::string(" in ") + (minExclusive ? "(" : "[") + boundText(min) + ", " +
               boundText(max) + (maxExclusive ? ")" : "]");
    } else if (hasMin) {
        out += std::string(minExclusive ? " > " : " >= ") + boundText(min);
    } else if (hasMax) {
        out += std::string(maxExclusive ? " < " : " <= ") + boundText(max);
    }
    return out;
}

namespace {

// The value of a JSON number as text for messages: integers as written, others shortest.
std::string numberText(const Json& value) {
    if (value.is_number_float()) return formatNumber(value.get<double>());
    return value.dump();
}

} // namespace

std::optional<float> readNumber(const JsonReader& reader, const Json& value,
                                const std::string& pointer, NumberRange range) {
    if (!value.is_number()) {
        reader.error(pointer, "expected " + range.describe() + ", got " + jsonTypeName(value));
        return std::nullopt;
    }
    const double v = value.get<double>();
    // Non-finite numbers (1e999 parses as infinity) were reported by parseJsonText.
    if (!std::isfinite(v)) return std::nullopt;
    // Halfway between the largest float and 2^128: doubles from here on round to infinity.
    constexpr double kFloatOverflow = 0x1.ffffffp127;
    if (std::abs(v) >= kFloatOverflow) {
        reader.error(pointer, "expected " + range.describe() + ", got " + numberText(value) +
                                  ", which is too large to represent");
        return std::nullopt;
    }
    // The float it is kept as must lie in the range: "0.001" is the float nearest 0.001, which
    // lies above 0.001 (a range's end written as a float, such as 0.001f, is that float), and a
    // number that rounds to 0 is 0 for a range that excludes it.
    const float kept = float(v);
    if (!range.contains(double(kept))) {
        reader.error(pointer, "expected " + range.describe() + ", got " + numberText(value));
        return std::nullopt;
    }
    return kept;
}

std::optional<int> readInteger(const JsonReader& reader, const Json& value,
                               const std::string& pointer, int lo, int hi) {
    const std::string expected =
        "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!value.is_number()) {
        reader.error(pointer, expected + ", got " + jsonTypeName(value));
        return std::nullopt;
    }
    const double v = value.get<double>();
    if (!std::isfinite(v)) return std::nullopt; // reported by parseJsonText
    if (v != std::floor(v) || v < lo || v > hi) {
        reader.error(pointer, expected + ", got " + numberText(value));
        return std::nullopt;
    }
    return int(v);
}

bool readNumbers(const JsonReader& reader, const Json& value, const std::string& pointer, int count,
                 float* out, NumberRange range) {
    if (!value.is_array() || value.size() != std::size_t(count)) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : jsonTypeName(value);
        reader.error(pointer,
                     "expected an array of " + std::to_string(count) + " numbers, got " + got);
        return false;
    }
    bool ok = true;
    for (int i = 0; i < count; ++i) {
        const auto v = readNumber(reader, value[std::size_t(i)], childPointer(pointer, i), range);
        if (v) {
            out[i] = *v;
        } else {
            ok = false;
        }
    }
    return ok;
}

std::optional<glm::vec3> readVec3(const JsonReader& reader, const Json& value,
                                  const std::string& pointer, NumberRange range) {
    float v[3];
    if (!readNumbers(reader, value, pointer, 3, v, range)) return std::nullopt;
    return glm::vec3(v[0], v[1], v[2]);
}

std::optional<std::string> readString(const JsonReader& reader, const Json& value,
                                      const std::string& pointer) {
    if (!value.is_string()) {
        reader.error(pointer, "expected a string, got " + jsonTypeName(value));
        return std::nullopt;
    }
    return value.get<std::string>();
}

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

} // namespace

std::optional<glm::vec3> readColor(const JsonReader& reader, const Json& value,
                                   const std::string& pointer) {
    if (value.is_array()) return readVec3(reader, value, pointer, NumberRange::atLeast(0.0));
    if (value.is_string()) {
        const std::string& text = value.get_ref<const std::string&>();
        glm::vec3 color{0.0f};
        bool ok = text.size() == 7 && text[0] == '#';
        for (int channel = 0; ok && channel < 3; ++channel) {
            const int hi = hexDigit(text[1 + 2 * channel]);
            const int lo = hexDigit(text[2 + 2 * channel]);
            ok = hi >= 0 && lo >= 0;
            if (ok) color[channel] = srgbToLinear(float(hi * 16 + lo) / 255.0f);
        }
        if (ok) return color;
        reader.error(pointer,
                     "expected a colour \"#rrggbb\" (sRGB, hexadecimal), got \"" + text + "\"");
        return std::nullopt;
    }
    reader.error(pointer, "expected a colour ([r, g, b] linear, or \"#rrggbb\" sRGB), got " +
                              jsonTypeName(value));
    return std::nullopt;
}

bool readNumberField(const JsonReader& reader, const Json& object, const std::string& pointer,
                     std::string_view key, float* out, NumberRange range) {
    const Json* value = findMember(object, key);
    if (!value) return true;
    const auto v = readNumber(reader, *value, childPointer(pointer, key), range);
    if (v) *out = *v;
    return v.has_value();
}

bool readIntegerField(const JsonReader& reader, const Json& object, const std::string& pointer,
                      std::string_view key, int* out, int lo, int hi) {
    const Json* value = findMember(object, key);
    if (!value) return true;
    const auto v = readInteger(reader, *value, childPointer(pointer, key), lo, hi);
    if (v) *out = *v;
    return v.has_value();
}

bool readVec3Field(const JsonReader& reader, const Json& object, const std::string& pointer,
                   std::string_view key, glm::vec3* out, NumberRange range) {
    const Json* value = findMember(object, key);
    if (!value) return true;
    const auto v = readVec3(reader, *value, childPointer(pointer, key), range);
    if (v) *out = *v;
    return v.has_value();
}

bool readStringField(const JsonReader& reader, const Json& object, const std::string& pointer,
                     std::string_view key, std::string* out) {
    const Json* value = findMember(object, key);
    if (!value) return true;
    const auto v = readString(reader, *value, childPointer(pointer, key));
    if (v) *out = *v;
    return v.has_value();
}

bool readColorField(const JsonReader& reader, const Json& object, const std::string& pointer,
                    std::string_view key, glm::vec3* out) {
    const Json* value = findMember(object, key);
    if (!value) return true;
    const auto v = readColor(reader, *value, childPointer(pointer, key));
    if (v) *out = *v;
    return v.has_value();
}

} // namespace rmsc
