// Disk with a per-session cache, then the embedded samples (see editor_file_source.hpp).
#include "editor_file_source.hpp"

#include <map>
#include <memory>

namespace rmsc::app {

FileSource editorFileSource() {
    auto cache = std::make_shared<std::map<std::filesystem::path, std::string>>();
    auto disk = std::make_shared<FileSource>(diskFileSource());
    auto embedded = std::make_shared<FileSource>(embeddedFileSource());
    FileSource source;
    source.read = [cache, disk, embedded](const std::filesystem::path& path,
                                          std::string& error) -> std::optional<std::string> {
        if (auto it = cache->find(path); it != cache->end()) return it->second;
        std::optional<std::string> bytes = disk->read(path, error);
        if (!bytes) {
            std::string embeddedError;
            bytes = embedded->read(path, embeddedError);
            if (!bytes) return std::nullopt;
            error.clear();
        }
        cache->emplace(path, *bytes);
        return bytes;
    };
    return source;
}

} // namespace rmsc::app
