// The recent files list and its file (see editor/recent_files.hpp).
#include "editor/recent_files.hpp"

#include "core/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace rmsc::editor {

std::filesystem::path recentFilesPath(const char* xdgConfigHome, const char* home) {
    if (xdgConfigHome && std::filesystem::path(xdgConfigHome).is_absolute())
        return std::filesystem::path(xdgConfigHome) / "rmsc" / "recent.json";
    if (home && *home) return std::filesystem::path(home) / ".config" / "rmsc" / "recent.json";
    return {};
}

std::filesystem::path recentFilesPath() {
    return recentFilesPath(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
}

std::vector<std::filesystem::path> loadRecentFiles(const std::filesystem::path& file,
                                                   std::string& error) {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    if (file.empty() || !std::filesystem::exists(file, ec)) return files;
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
    const auto expected = [&](const std::string& where, const std::string& what) {
        error = file.string() + ": " + where + ": expected " + what;
        return std::vector<std::filesystem::path>{};
    };
    if (json.is_discarded() || !json.is_object())
        return expected("", "a JSON object {\"files\": [...]}");
    const auto list = json.find("files");
    if (list == json.end() || !list->is_array())
        return expected("/files", "an array of file paths");
    for (std::size_t i = 0; i < list->size(); ++i) {
        const nlohmann::json& entry = (*list)[i];
        if (!entry.is_string() || entry.get<std::string>().empty())
            return expected("/files/" + std::to_string(i), "a file path (a string)");
        if (files.size() < kMaxRecentFiles) files.emplace_back(entry.get<std::string>());
    }
    return files;
}

bool saveRecentFiles(const std::filesystem::path& file,
                     const std::vector<std::filesystem::path>& files, std::string& error) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    if (ec) {
        error = file.parent_path().string() + ": cannot make the folder: " + ec.message();
        return false;
    }
    nlohmann::json list = nlohmann::json::array();
    for (const std::filesystem::path& path : files)
        list.push_back(path.string());
    const std::string text = nlohmann::json{{"files", list}}.dump(2) + "\n";
    return saveTextFileAtomically(file, text, false, error);
}

void addRecentFile(std::vector<std::filesystem::path>& files, const std::filesystem::path& file) {
    const std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
    files.erase(std::remove(files.begin(), files.end(), absolute), files.end());
    files.insert(files.begin(), absolute);
    if (files.size() > kMaxRecentFiles) files.resize(kMaxRecentFiles);
}

void removeMissingFiles(std::vector<std::filesystem::path>& files) {
    files.erase(std::remove_if(files.begin(), files.end(),
                               [](const std::filesystem::path& path) {
                                   std::error_code ec;
                                   return !std::filesystem::exists(path, ec);
                               }),
                files.end());
}

} // namespace rmsc::editor
