// Modification-time polling (see file_watcher.hpp).
#include "editor/file_watcher.hpp"

namespace rmsc::editor {

FileWatcher::Stamps FileWatcher::scan() const {
    namespace fs = std::filesystem;
    Stamps stamps;
    if (path_.empty()) return stamps;
    std::error_code ec;
    if (fs::is_directory(path_, ec)) {
        for (auto it = fs::recursive_directory_iterator(path_, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            if (it->is_regular_file(ec)) stamps[it->path()] = it->last_write_time(ec);
        }
    } else {
        const auto time = fs::last_write_time(path_, ec);
        if (!ec) stamps[path_] = time;
    }
    return stamps;
}

bool FileWatcher::changed() {
    Stamps now = scan();
    if (now == stamps_) return false;
    stamps_ = std::move(now);
    return true;
}

void FileWatcher::sync() {
    stamps_ = scan();
}

} // namespace rmsc::editor
