// Saving files so that nothing is lost: the new content goes to a temporary file in the same
// folder, is flushed to the disk (fsync), and only then renamed over the old file, so a crash
// or a full disk never leaves a half-written file. The previous version can be kept as
// "<name>.bak". Used for every file rmsc writes (images, scenes). Saving to a symbolic link
// writes the file at the end of its links (as editors do): the link stays a link, the file it
// points to gets the new content, and its backup is "<that file>.bak" beside it.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
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

// The file a save to `path` replaces: `path`, or the end of its chain of symbolic links (at
// most 40). A dangling link gives the missing file it names. nullopt with `error` set for a
// link loop or an unreadable link.
std::optional<std::filesystem::path> saveTarget(const std::filesystem::path& path,
                                                std::string& error);

// "<path>.bak": where the previous content is kept.
std::filesystem::path backupPath(const std::filesystem::path& path);

} // namespace rmsc
