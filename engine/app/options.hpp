// A small command-line parser: each subcommand declares its options once (name, value name,
// help), and the same table parses arguments and prints --help.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rmsc::app {

struct OptionSpec {
    const char* name;      // "--size" (and optionally a short form in `shortName`)
    const char* shortName; // "-o" or nullptr
    const char* valueName; // "WxH", or nullptr for a flag
    const char* help;
};

struct CommandSpec {
    const char* name;      // "render"
    const char* arguments; // "[SCENE] -o OUT.png": the short form `rmsc --help` lists
    const char* purpose;   // one line for `rmsc --help`: "render a scene ... to PNG"
    const char* usage;     // "rmsc render [SCENE] -o OUT.png [options]"
    const char* summary;   // one paragraph
    std::span<const OptionSpec> options;
    int maxPositionals; // how many positional arguments are allowed
};

struct ParsedArgs {
    std::map<std::string, std::string> values; // by long name; flags map to ""
    std::vector<std::string> positionals;
    bool help = false;

    bool has(const std::string& name) const { return values.contains(name); }
    std::string get(const std::string& name, const std::string& fallback) const;
};

// Parses `args` (without the program and command names). Returns nullopt and sets `error` on
// an unknown option, a missing value or too many positional arguments.
std::optional<ParsedArgs> parseArgs(const CommandSpec& spec, std::span<const std::string> args,
                                    std::string& error);

std::string formatHelp(const CommandSpec& spec);

// --sandbox DIR, listed by every command that reads scenes (render, validate, bench, view).
inline constexpr OptionSpec kSandboxOption = {
    "--sandbox", nullptr, "DIR",
    "every file read for the scene must resolve inside DIR (outputs are not confined)"};
// Applies --sandbox, when given, to every disk read of the process (setDiskReadSandbox), before
// the command reads anything. Prints the problem and returns false when DIR is not a folder.
bool applySandboxOption(const CommandSpec& spec, const ParsedArgs& args);

// Parses "640x360"; sizes from 1 to limits::kImageSize per side.
bool parseSize(const std::string& text, int& width, int& height);
// What --size takes, for messages.
std::string sizeExpectation();
// Parses a positive integer up to `max`.
bool parsePositiveInt(const std::string& text, int max, int& value);

} // namespace rmsc::app
