// Saving files so that nothing is lost: the new content goes to a temporary file in the same
// folder, is flushed to the disk (fsync), and only then renamed over the old file, so a crash
// or a full disk never leaves a half-written file. The previous version can be kept as
// "<name>.bak". Used for every file rmsc writes (images, scenes).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace rmsc {

// Writes `text` to `path` atomically. With keepBackup, an existing `path` is first copied to
// "<path>.bak" (replacing an older backup). Returns false with `error` saying why when the
// file could not be written; `path` is then unchanged.
bool saveTextFileAtomically(const std::filesystem::path& path, std::string_view text,
                            bool keepBackup, std::string& error);

// The mechanism under saveTextFileAtomically, for writers that produce the file themselves
// (PNG encoders): `writeTemporary(tmp)` writes the complete file at `tmp` (a unique path in
// the same folder as `path`) and returns false on failure, optionally setting `error`. The
// temporary file is then fsync'ed and renamed over `path`, or removed on failure.
bool replaceFileAtomically(
    const std::filesystem::path& path, bool keepBackup, std::string& error,
    const std::function<bool(const std::filesystem::path& tmp)>& writeTemporary);

// "<path>.bak": where the previous content is kept.
std::filesystem::path backupPath(const std::filesystem::path& path);

} // namespace rmsc
