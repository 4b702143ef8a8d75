// rmsc primitives: prints the primitive catalogue (names, parameters, exact or bound), then the
// profile shapes (extrusion, revolution) and the 2D profiles they take.
#include "commands.hpp"

#include "sdf/catalogue_docs.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--markdown", nullptr, nullptr, "print the table used in docs/scene-format.md"},
};

// "(0, 10000]", "[0, 10000]"; "" when unbounded.
std::string rangeText(const ParamRange& range) {
    if (!std::isfinite(range.min) || !std::isfinite(range.max)) return "";
    char text[64];
    std::snprintf(text, sizeof text, "%s%g, %g%s", range.minExclusive ? "(" : "[", range.min,
                  range.max, range.maxExclusive ? ")" : "]");
    return text;
}

// A profile's or a profile shape's key: its default (or "required") and range.
void printParam(const SdfParamSpec& p) {
    std::string value = "required";
    if (!p.required) {
        const int count = p.type == ParamType::Vec2 ? 2 : 1;
        value.clear();
        for (int c = 0; c < count; ++c) {
            char text[32];
            std::snprintf(text, sizeof text, "%s%g", c ? ", " : "", double(p.value[c]));
            value += text;
        }
        if (count > 1) value = "[" + value + "]";
    }
    const std::string range = rangeText(p.range);
    const std::string_view unit = unitPhrase(p.range.unit);
    std::printf("    %-14s %-16s %s%s%s%s%s\n", std::string(p.key).c_str(), value.c_str(),
                range.empty() ? "" : "range ", range.c_str(), unit.empty() ? "" : ", ",
                std::string(unit).c_str(), ("  " + std::string(p.description)).c_str());
}

} // namespace

const CommandSpec kPrimitivesSpec = {
    "primitives",
    "",
    "list the SDF primitives and their parameters",
    "rmsc primitives [--markdown]",
    "Lists every SDF primitive a scene can use, with its parameters (default and valid range)\n"
    "and whether its distance is exact or a bound, then the shapes made of a 2D profile\n"
    "(extrusion, revolution) and the profiles they take.",
    kOptions,
    0};

int runPrimitives(const ParsedArgs& args) {
    if (args.has("--markdown")) {
        std::fputs(primitiveCatalogueMarkdown().c_str(), stdout);
        return kExitOk;
    }
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        std::printf("%s (%s): %s\n", std::string(spec.name).c_str(), spec.exact ? "exact" : "bound",
                    std::string(spec.description).c_str());
        for (const ParamSpec& p : spec.params) {
            std::string value;
            for (int c = 0; c < p.components; ++c) {
                char text[32];
                std::snprintf(text, sizeof text, "%s%g", c ? ", " : "", double(p.value[c]));
                value += text;
            }
            if (p.components > 1) value = "[" + value + "]";
            const std::string_view unit = unitPhrase(p.unit);
            std::printf("    %-14s %-16s range [%g, %g]%s%s  %s\n", std::string(p.name).c_str(),
                        value.c_str(), double(p.minValue), double(p.maxValue),
                        unit.empty() ? "" : ", ", std::string(unit).c_str(),
                        std::string(p.description).c_str());
        }
    }
    std::string profiles;
    for (const ProfileSpec& profile : profileCatalogue())
        profiles += (profiles.empty() ? "" : ", ") + std::string(profile.name);
    for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
        std::printf("%s (profile shape): %s\n", std::string(solid.name).c_str(),
                    std::string(solid.description).c_str());
        std::printf("    %-14s %-16s a profile object, \"type\" one of: %s (below)\n", "profile",
                    "required", profiles.c_str());
        printParam(solid.param.spec);
    }
    std::printf("\nProfiles (the \"profile\" of an extrusion or a revolution):\n");
    for (const ProfileSpec& profile : profileCatalogue()) {
        std::printf("%s: %s\n", std::string(profile.name).c_str(),
                    std::string(profile.description).c_str());
        for (const ProfileParam& param : profile.params)
            printParam(param.spec);
    }
    return kExitOk;
}

} // namespace rmsc::app
