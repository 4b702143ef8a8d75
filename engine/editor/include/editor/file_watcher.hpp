// Noticing external edits by polling modification times: a watched file, or every file under
// a folder. `changed()` is true once per change; `sync()` accepts the current state (after the
// program itself wrote the file). GL-free.
#pragma once

#include <filesystem>
#include <map>

namespace rmsc::editor {

class FileWatcher {
  public:
    FileWatcher() = default;
    explicit FileWatcher(std::filesystem::path path) : path_(std::move(path)) { sync(); }

    const std::filesystem::path& path() const { return path_; }
    // True when any watched file was modified, created or removed since the last call / sync.
    bool changed();
    void sync();

  private:
    using Stamps = std::map<std::filesystem::path, std::filesystem::file_time_type>;
    std::filesystem::path path_;
    Stamps stamps_;
    Stamps scan() const;
};

} // namespace rmsc::editor
