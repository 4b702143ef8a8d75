// The file browser's filters and listings (see editor/file_browser.hpp).
#include "editor/file_browser.hpp"

#include <algorithm>
#include <cctype>

namespace rmsc::editor {
namespace {

constexpr std::string_view kScene[] = {".json"};
constexpr std::string_view kMesh[] = {".gltf", ".glb"};
constexpr std::string_view kTexture[] = {".png", ".jpg", ".jpeg"};
constexpr std::string_view kSky[] = {".hdr", ".png", ".jpg", ".jpeg"};

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

} // namespace

std::string_view fileKindLabel(FileKind kind) {
    switch (kind) {
    case FileKind::Scene:
        return "Scene files (.json)";
    case FileKind::Mesh:
        return "glTF models (.gltf, .glb)";
    case FileKind::Texture:
        return "Images (.png, .jpg, .jpeg)";
    case FileKind::Sky:
        return "Sky images (.hdr, .png, .jpg, .jpeg)";
    }
    return "";
}

std::span<const std::string_view> fileKindExtensions(FileKind kind) {
    switch (kind) {
    case FileKind::Scene:
        return kScene;
    case FileKind::Mesh:
        return kMesh;
    case FileKind::Texture:
        return kTexture;
    case FileKind::Sky:
        return kSky;
    }
    return {};
}

bool matchesFileKind(const std::filesystem::path& path, FileKind kind) {
    const std::string extension = lower(path.extension().string());
    const std::span<const std::string_view> wanted = fileKindExtensions(kind);
    return std::find(wanted.begin(), wanted.end(), extension) != wanted.end();
}

DirectoryListing listDirectory(const std::filesystem::path& folder, FileKind kind, bool allFiles) {
    DirectoryListing listing;
    listing.folder = folder;
    std::error_code ec;
    std::filesystem::directory_iterator it(folder, ec);
    if (ec) {
        listing.error = folder.string() + ": " + ec.message();
        return listing;
    }
    for (const std::filesystem::directory_iterator end; it != end; it.increment(ec)) {
        if (ec) {
            listing.error = folder.string() + ": " + ec.message();
            break;
        }
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code typeError;
        const bool isFolder = it->is_directory(typeError); // follows links
        if (isFolder) {
            listing.entries.push_back({name, true, 0});
        } else if (allFiles || matchesFileKind(it->path(), kind)) {
            std::error_code sizeError;
            const std::uintmax_t bytes = it->file_size(sizeError);
            listing.entries.push_back({name, false, sizeError ? 0 : bytes});
        }
    }
    std::sort(listing.entries.begin(), listing.entries.end(),
              [](const DirectoryEntry& a, const DirectoryEntry& b) {
                  if (a.folder != b.folder) return a.folder;
                  const std::string la = lower(a.name), lb = lower(b.name);
                  return la != lb ? la < lb : a.name < b.name;
              });
    return listing;
}

std::filesystem::path typedPath(const std::filesystem::path& folder, std::string_view typed,
                                const std::filesystem::path& home) {
    std::string text(typed);
    if (!home.empty() && (text == "~" || text.rfind("~/", 0) == 0))
        return (home / text.substr(std::min<std::size_t>(2, text.size()))).lexically_normal();
    const std::filesystem::path path(text);
    return (path.is_absolute() ? path : folder / path).lexically_normal();
}

std::string fileFieldText(const std::filesystem::path& chosen,
                          const std::filesystem::path& sceneFolder) {
    const std::filesystem::path file = chosen.lexically_normal();
    if (!sceneFolder.empty()) {
        const std::filesystem::path relative =
            file.lexically_relative(sceneFolder.lexically_normal());
        if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    }
    return file.string();
}

} // namespace rmsc::editor
