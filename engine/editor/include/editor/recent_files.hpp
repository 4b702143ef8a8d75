// The files opened or saved last (File > Open Recent), newest first and at most kMaxRecentFiles,
// kept in $XDG_CONFIG_HOME/rmsc/recent.json (~/.config/rmsc/recent.json without it) as
// {"files": ["/abs/path.json", ...]} and written atomically. A file that no longer exists stays
// listed (the menu shows it greyed) until the user removes the missing ones. GL-free.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rmsc::editor {

inline constexpr std::size_t kMaxRecentFiles = 10;

// Where the list is kept: under `xdgConfigHome` when it is set and absolute (the XDG base
// directory rule), else under `home`/.config; empty when neither is usable.
std::filesystem::path recentFilesPath(const char* xdgConfigHome, const char* home);
// The same from the environment ($XDG_CONFIG_HOME, $HOME).
std::filesystem::path recentFilesPath();

// Reads the list; a missing file is an empty list. A file that is not such a list gives an
// empty list with `error` naming the file and what was expected.
std::vector<std::filesystem::path> loadRecentFiles(const std::filesystem::path& file,
                                                   std::string& error);
// Writes the list atomically, making its folder when needed; false with `error` on failure.
bool saveRecentFiles(const std::filesystem::path& file,
                     const std::vector<std::filesystem::path>& files, std::string& error);

// `file` (made absolute and lexically normal) becomes the first entry, once; the list keeps
// kMaxRecentFiles entries.
void addRecentFile(std::vector<std::filesystem::path>& files, const std::filesystem::path& file);
// Drops the entries whose file does not exist.
void removeMissingFiles(std::vector<std::filesystem::path>& files);

} // namespace rmsc::editor
