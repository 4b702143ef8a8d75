// #include resolution with #line bookkeeping, and mapping compiler logs back to files.
#include "gl/shader_source.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace rmsc {
namespace {

struct Assembler {
    const ShaderFiles& files;
    AssembledShader out;
    std::set<std::string, std::less<>> included;
    std::string error;

    int fileIndex(std::string_view path) {
        out.files.emplace_back(path);
        return int(out.files.size()) - 1;
    }

    // Appends `text` of file `index`; `isRoot` keeps the #version line first.
    bool append(std::string_view path, const std::string& text, std::string_view defines,
                int depth) {
        if (depth > 32) {
            error = std::string(path) + ": includes nested more than 32 deep";
            return false;
        }
        const int index = int(out.files.size()) - 1;
        std::istringstream lines(text);
        std::string line;
        int lineNumber = 0;
        const bool isRoot = depth == 0;
        if (!isRoot) out.text += "#line 1 " + std::to_string(index) + "\n";
        while (std::getline(lines, line)) {
            ++lineNumber;
            const std::size_t first = line.find_first_not_of(" \t");
            const std::string_view trimmed = first == std::string::npos
                                                 ? std::string_view()
                                                 : std::string_view(line).substr(first);
            if (trimmed.starts_with("#version")) {
                if (!isRoot || lineNumber != 1) {
                    error = std::string(path) + ":" + std::to_string(lineNumber) +
                            ": #version must be the first line of the main shader file";
                    return false;
                }
                out.text += line + "\n" + std::string(defines) + "#line 2 0\n";
                continue;
            }
            if (trimmed.starts_with("#include")) {
                const std::size_t open = trimmed.find('"');
                const std::size_t close = trimmed.find('"', open + 1);
                if (open == std::string_view::npos || close == std::string_view::npos) {
                    error = std::string(path) + ":" + std::to_string(lineNumber) +
                            ": expected #include \"file\"";
                    return false;
                }
                const std::string target(trimmed.substr(open + 1, close - open - 1));
                if (!included.contains(target)) {
                    included.insert(target);
                    const std::optional<std::string> source = files.find(target);
                    if (!source) {
                        error = std::string(path) + ":" + std::to_string(lineNumber) +
                                ": included file \"" + target + "\" not found";
                        return false;
                    }
                    fileIndex(target);
                    if (!append(target, *source, defines, depth + 1)) return false;
                }
                out.text +=
                    "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
                continue;
            }
            out.text += line + "\n";
        }
        return true;
    }
};

} // namespace

std::optional<std::string> ShaderFiles::find(std::string_view path) const {
    if (!overrideDirectory.empty() && !path.starts_with("generated/")) {
        std::ifstream in(overrideDirectory + "/" + std::string(path), std::ios::binary);
        if (in) {
            std::ostringstream text;
            text << in.rdbuf();
            return std::move(text).str();
        }
    }
    const auto it = files.find(path);
    if (it == files.end()) return std::nullopt;
    return it->second;
}

std::optional<AssembledShader> assembleShader(const ShaderFiles& files, std::string_view path,
                                              std::string_view defines, std::string& error) {
    Assembler assembler{files, {}, {}, {}};
    const std::optional<std::string> source = files.find(path);
    if (!source) {
        error = "shader \"" + std::string(path) + "\" not found";
        return std::nullopt;
    }
    assembler.included.insert(std::string(path));
    assembler.fileIndex(path);
    if (!assembler.append(path, *source, defines, 0)) {
        error = assembler.error;
        return std::nullopt;
    }
    return std::move(assembler.out);
}

std::string mapShaderLog(const AssembledShader& shader, std::string_view log) {
    // Mesa writes "0:12(5): error: ...", other drivers "0(12) : error ...".
    static const std::regex location(R"((^|\n)(\d+)(?::(\d+)\((\d+)\)|\((\d+)\)))");
    std::string out;
    std::string text(log);
    std::smatch match;
    auto begin = text.cbegin();
    while (std::regex_search(begin, text.cend(), match, location)) {
        out.append(begin, match[0].first);
        const std::size_t fileIndex = std::stoul(match[2].str());
        const std::string file =
            fileIndex < shader.files.size() ? shader.files[fileIndex] : match[2].str();
        const std::string line = match[3].matched ? match[3].str() : match[5].str();
        out += match[1].str() + file + ":" + line;
        if (match[4].matched) out += ":" + match[4].str();
        begin = match[0].second;
    }
    out.append(begin, text.cend());
    return out;
}

std::string mapLinkLog(std::span<const ShaderStageSource> stages, std::string_view log) {
    const AssembledShader* current = stages.size() == 1 ? stages[0].source : nullptr;
    std::string out;
    std::size_t start = 0;
    while (start < log.size()) {
        std::size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        const std::string_view line = log.substr(start, end - start);
        for (const ShaderStageSource& stage : stages)
            if (line.starts_with(std::string(stage.stage) + " info")) current = stage.source;
        out += current ? mapShaderLog(*current, line) : std::string(line);
        if (end < log.size()) out += '\n';
        start = end + 1;
    }
    return out;
}

} // namespace rmsc
