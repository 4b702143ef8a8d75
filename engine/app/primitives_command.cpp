// rmsc primitives: prints the primitive catalogue (names, parameters, exact or bound).
#include "commands.hpp"

#include "sdf/catalogue_docs.hpp"
#include "sdf/primitives.hpp"

#include <cstdio>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--markdown", nullptr, nullptr, "print the table used in docs/scene-format.md"},
};

} // namespace

const CommandSpec kPrimitivesSpec = {
    "primitives",
    "",
    "list the SDF primitives and their parameters",
    "rmsc primitives [--markdown]",
    "Lists every SDF primitive a scene can use, with its parameters (default and valid range)\n"
    "and whether its distance is exact or a bound.",
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
            std::printf("    %-14s %-16s range [%g, %g]  %s\n", std::string(p.name).c_str(),
                        value.c_str(), double(p.minValue), double(p.maxValue),
                        std::string(p.description).c_str());
        }
    }
    return kExitOk;
}

} // namespace rmsc::app
