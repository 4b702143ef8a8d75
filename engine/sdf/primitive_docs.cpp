// The markdown table of SDF primitives, generated from the catalogue rows.
#include "sdf/primitive_docs.hpp"

#include "sdf/primitives.hpp"

#include <charconv>

namespace rmsc {
namespace {

// Shortest text that reads back as the same float, in plain digits: 0.15f -> "0.15".
std::string number(float value) {
    char buffer[128];
    const float magnitude = value < 0 ? -value : value;
    const bool fixed = magnitude == 0 || (magnitude >= 1e-5f && magnitude < 1e15f);
    const auto result =
        fixed ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
              : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

// Table cells must not contain a bare "|".
std::string cell(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}

std::string paramText(const ParamSpec& param) {
    std::string out = "`" + std::string(param.name) + "`: ";
    if (param.components == 1) {
        out += "number, default " + number(param.value[0]);
    } else {
        out += "[x, y, z], default [" + number(param.value[0]) + ", " + number(param.value[1]) +
               ", " + number(param.value[2]) + "]";
    }
    out += ", range [" + number(param.minValue) + ", " + number(param.maxValue) + "]";
    if (param.components == 3) out += " per component";
    out += " — " + cell(param.description);
    return out;
}

} // namespace

std::string primitiveCatalogueMarkdown() {
    std::string out = "| Shape | Parameters | Distance | Description |\n"
                      "|---|---|---|---|\n";
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        std::string params;
        for (const ParamSpec& param : spec.params) {
            if (!params.empty()) params += "<br>";
            params += paramText(param);
        }
        out += "| `" + std::string(spec.name) + "` | " + params + " | " +
               (spec.exact ? "exact" : "bound") + " | " + cell(spec.description) + " |\n";
    }
    return out;
}

} // namespace rmsc
