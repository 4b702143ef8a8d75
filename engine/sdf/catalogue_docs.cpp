// The markdown tables of the catalogues (primitives, modifiers, operations, profiles),
// generated from their rows.
#include "sdf/catalogue_docs.hpp"

#include "core/number_text.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {
namespace {

std::string number(double value) {
    const float asFloat = float(value);
    return double(asFloat) == value ? shortestNumberText(asFloat) : shortestNumberText(value);
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
    if (param.unit != Unit::None) out += ", " + std::string(unitPhrase(param.unit));
    out += " — " + cell(param.description);
    return out;
}

// "[0, 10000]", "(0, 10000]"; "" when unbounded.
std::string rangeText(const ParamRange& range) {
    if (!std::isfinite(range.min) || !std::isfinite(range.max)) return "";
    return std::string(range.minExclusive ? "(" : "[") + number(range.min) + ", " +
           number(range.max) + (range.maxExclusive ? ")" : "]");
}

std::string list(const std::array<float, 3>& v, int count) {
    std::string out = "[";
    for (int c = 0; c < count; ++c)
        out += (c ? ", " : "") + number(v[std::size_t(c)]);
    return out + "]";
}

// The JSON form of a parameter and, for optional ones, its default as written in a file.
std::string typeText(const SdfParamSpec& spec, std::string& defaultText) {
    const std::array<float, 3>& v = spec.value;
    switch (spec.type) {
    case ParamType::Number:
        defaultText = number(v[0]);
        return "number";
    case ParamType::Integer:
        defaultText = number(v[0]);
        return "integer";
    case ParamType::Vec2:
        defaultText = list(v, 2);
        return "[x, y]";
    case ParamType::Vec3:
        defaultText = list(v, 3);
        return "[x, y, z]";
    case ParamType::IVec3:
        defaultText = list(v, 3);
        return "[x, y, z] of integers";
    case ParamType::Bool:
        defaultText = v[0] != 0.0f ? "true" : "false";
        return "true or false";
    case ParamType::Axes:
        defaultText = "";
        return "string of one to three different axes";
    case ParamType::Axis:
        defaultText = std::string("\"") + "xyz"[std::size_t(std::clamp(int(v[0]), 0, 2))] + "\"";
        return "\"x\", \"y\" or \"z\"";
    case ParamType::Points:
        defaultText = "";
        return "[[x, y], ...], " + std::to_string(kMinPolygonPoints) + " to " +
               std::to_string(kMaxPolygonPoints) + " points";
    }
    return "";
}

std::string paramText(const SdfParamSpec& spec) {
    std::string defaultText;
    std::string out = "`" + std::string(spec.key) + "`: " + typeText(spec, defaultText);
    out += spec.required ? ", required" : ", default " + defaultText;
    const std::string range = rangeText(spec.range);
    if (!range.empty()) {
        out += ", range " + range;
        if (spec.type == ParamType::Vec2 || spec.type == ParamType::Vec3 ||
            spec.type == ParamType::IVec3)
            out += " per component";
        if (spec.type == ParamType::Points) out += " per coordinate";
    }
    if (spec.range.unit != Unit::None) out += ", " + std::string(unitPhrase(spec.range.unit));
    return out + " — " + cell(spec.description);
}

template <typename Params> std::string paramsText(const Params& params) {
    std::string out;
    for (const auto& param : params) {
        if (!out.empty()) out += "<br>";
        out += paramText(param.spec);
    }
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

std::string modifierCatalogueMarkdown() {
    std::string out = "| Modifier | Acts on | Parameters | Description |\n"
                      "|---|---|---|---|\n";
    for (const ModifierSpec& spec : modifierCatalogue()) {
        out += "| `" + std::string(spec.name) + "` | " +
               (spec.stage == ModifierStage::Point ? "point" : "distance") + " | " +
               paramsText(spec.params) + " | " + cell(spec.description) + " |\n";
    }
    return out;
}

std::string operationCatalogueMarkdown() {
    std::string out = "| `op` | `smoothness` | `blend` | Result |\n"
                      "|---|---|---|---|\n";
    for (const OperationSpec& spec : operationCatalogue()) {
        out += "| `" + std::string(spec.name) + "` | " +
               (takesSmoothness(spec.op) ? "required" : "ignored") + " | " +
               (takesBlend(spec.op) ? "optional" : "ignored") + " | " + cell(spec.description) +
               " |\n";
    }
    return out;
}

std::string profileCatalogueMarkdown() {
    std::string out = "| Shape | Keys | Description |\n"
                      "|---|---|---|\n";
    for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
        out += "| `" + std::string(solid.name) +
               "` | `profile`: a profile object (below), required<br>" +
               paramText(solid.param.spec) + " | " + cell(solid.description) + " |\n";
    }
    out += "\n| Profile `type` | Parameters | Description |\n"
           "|---|---|---|\n";
    for (const ProfileSpec& spec : profileCatalogue()) {
        out += "| `" + std::string(spec.name) + "` | " + paramsText(spec.params) + " | " +
               cell(spec.description) + " |\n";
    }
    return out;
}

} // namespace rmsc
