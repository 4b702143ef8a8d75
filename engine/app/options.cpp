// Command-line parsing and help text.
#include "options.hpp"

#include "core/file_source.hpp"
#include "core/limits.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>

namespace rmsc::app {

std::string ParsedArgs::get(const std::string& name, const std::string& fallback) const {
    auto it = values.find(name);
    return it == values.end() ? fallback : it->second;
}

std::optional<ParsedArgs> parseArgs(const CommandSpec& spec, std::span<const std::string> args,
                                    std::string& error) {
    ParsedArgs parsed;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--help" || arg == "-h") {
            parsed.help = true;
            continue;
        }
        if (arg.size() > 1 && arg[0] == '-') {
            std::string name = arg, value;
            bool inlineValue = false;
            if (const std::size_t eq = arg.find('='); arg.starts_with("--") && eq != arg.npos) {
                name = arg.substr(0, eq);
                value = arg.substr(eq + 1);
                inlineValue = true;
            }
            const OptionSpec* option = nullptr;
            for (const OptionSpec& o : spec.options)
                if (name == o.name || (o.shortName && name == o.shortName)) option = &o;
            if (!option) {
                error = "unknown option " + name + " (see rmsc " + spec.name + " --help)";
                return std::nullopt;
            }
            if (option->valueName && !inlineValue) {
                if (i + 1 >= args.size()) {
                    error = std::string(option->name) + " needs a value: " + option->valueName;
                    return std::nullopt;
                }
                value = args[++i];
            } else if (!option->valueName && inlineValue) {
                error = std::string(option->name) + " takes no value";
                return std::nullopt;
            }
            parsed.values[option->name] = value;
            continue;
        }
        parsed.positionals.push_back(arg);
    }
    if (int(parsed.positionals.size()) > spec.maxPositionals && !parsed.help) {
        error = "too many arguments (see rmsc " + std::string(spec.name) + " --help)";
        return std::nullopt;
    }
    return parsed;
}

std::string formatHelp(const CommandSpec& spec) {
    std::string out = std::string("usage: ") + spec.usage + "\n\n" + spec.summary + "\n";
    if (!spec.options.empty()) out += "\noptions:\n";
    for (const OptionSpec& o : spec.options) {
        std::string left = "  ";
        if (o.shortName) left += std::string(o.shortName) + ", ";
        left += o.name;
        if (o.valueName) left += std::string(" ") + o.valueName;
        if (left.size() < 28)
            left.resize(28, ' ');
        else
            left += "  ";
        out += left + o.help + "\n";
    }
    out += "  -h, --help                show this help\n";
    return out;
}

bool applySandboxOption(const CommandSpec& spec, const ParsedArgs& args) {
    if (!args.has(kSandboxOption.name)) return true;
    const std::string folder = args.get(kSandboxOption.name, "");
    std::error_code ec;
    const auto status = std::filesystem::status(folder, ec);
    if (folder.empty() || !std::filesystem::is_directory(status)) {
        std::fprintf(stderr, "rmsc %s: --sandbox: expected a folder, got '%s' (%s)\n", spec.name,
                     folder.c_str(),
                     std::filesystem::exists(status) ? "not a folder" : "not found");
        return false;
    }
    setDiskReadSandbox(folder);
    return true;
}

bool parsePositiveInt(const std::string& text, int max, int& value) {
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < 1 || v > max) return false;
    value = v;
    return true;
}

bool parseSize(const std::string& text, int& width, int& height) {
    const std::size_t x = text.find('x');
    if (x == std::string::npos) return false;
    return parsePositiveInt(text.substr(0, x), limits::kImageSize, width) &&
           parsePositiveInt(text.substr(x + 1), limits::kImageSize, height) &&
           std::int64_t(width) * height <= limits::kImagePixels;
}

std::string sizeExpectation() {
    return "WxH with sides 1.." + std::to_string(limits::kImageSize) + " and at most " +
           std::to_string(limits::kImagePixels) + " pixels (a frame takes about 70 bytes a pixel)";
}

} // namespace rmsc::app
