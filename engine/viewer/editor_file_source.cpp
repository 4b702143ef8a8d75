// Disk with a per-session cache, then the embedded samples (see editor_file_source.hpp).
#include "editor_file_source.hpp"

#include <map>
#include <memory>
#include <utility>

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
    // glTF buffers and images: held to their folder by the disk source (links resolved), so
    // they are cached apart from plain reads, which are not.
    auto insideCache = std::make_shared<
        std::map<std::pair<std::filesystem::path, std::filesystem::path>, std::string>>();
    source.readInside = [insideCache, disk,
                         embedded](const std::filesystem::path& folder,
                                   const std::filesystem::path& relative,
                                   std::string& error) -> std::optional<std::string> {
        const auto key = std::make_pair(folder, relative);
        if (auto it = insideCache->find(key); it != insideCache->end()) return it->second;
        std::optional<std::string> bytes = readInsideFolder(*disk, folder, relative, error);
        if (!bytes) {
            std::string embeddedError;
            bytes = readInsideFolder(*embedded, folder, relative, embeddedError);
            if (!bytes) return std::nullopt;
            error.clear();
        }
        insideCache->emplace(key, *bytes);
        return bytes;
    };
    return source;
}

} // namespace rmsc::app
