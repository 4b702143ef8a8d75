// FileSource implementations: the disk and the files embedded in the binary.
#include "core/file_source.hpp"

#include "core/embedded.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

namespace rmsc {

FileSource diskFileSource(std::uintmax_t maxBytes) {
    return {[maxBytes](const std::filesystem::path& path,
                       std::string& error) -> std::optional<std::string> {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            error = "file not found";
            return std::nullopt;
        }
        if (std::filesystem::is_directory(path, ec)) {
            error = "is a directory, expected a file";
            return std::nullopt;
        }
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        if (!ec && size > maxBytes) {
            error = "file is " + std::to_string(size) + " bytes, more than the limit of " +
                    std::to_string(maxBytes);
            return std::nullopt;
        }
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            error = "cannot open file for reading";
            return std::nullopt;
        }
        std::ostringstream bytes;
        bytes << in.rdbuf();
        if (in.bad()) {
            error = "read error";
            return std::nullopt;
        }
        return std::move(bytes).str();
    }};
}

FileSource embeddedFileSource() {
    return {[](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
        const std::string key = path.lexically_normal().generic_string();
        for (const EmbeddedFile& f : embeddedSamples())
            if (f.path == key) return std::string(f.data);
        error = "not among the files built into rmsc";
        return std::nullopt;
    }};
}

} // namespace rmsc
