// Atomic file replacement (see atomic_file.hpp): temporary file, fsync, rename, then fsync of
// the folder so the rename itself is durable (POSIX rename(2) is atomic within a file system).
// A save through a symbolic link replaces the file the link leads to, not the link.
#include "core/atomic_file.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <system_error>
#include <unistd.h>

namespace rmsc {
namespace {

std::string systemError(int code) {
    return std::strerror(code);
}

// Flushes an existing file's data to the disk.
bool syncFile(const std::filesystem::path& path, std::string& error) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        error = "cannot open " + path.string() + " to flush it: " + systemError(errno);
        return false;
    }
    const bool ok = ::fsync(fd) == 0;
    if (!ok) error = "cannot flush " + path.string() + " to the disk: " + systemError(errno);
    ::close(fd);
    return ok;
}

// Best effort: some file systems refuse fsync on folders, which is not a failure of the save.
void syncFolder(const std::filesystem::path& folder) {
    const int fd =
        ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
}

// Temporaries of earlier saves of `path` that never finished (the process was killed between
// creating and renaming them): "<name>.tmp-XXXXXX" files older than an hour, so a save still
// running in another process keeps its own. Best effort.
void removeStaleTemporaries(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const std::string prefix = path.filename().string() + ".tmp-";
    const auto cutoff = fs::file_time_type::clock::now() - std::chrono::hours(1);
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() != prefix.size() + 6 || !name.starts_with(prefix)) continue;
        std::error_code fileError;
        if (!it->is_regular_file(fileError) || it->is_symlink(fileError)) continue;
        const auto written = fs::last_write_time(it->path(), fileError);
        if (!fileError && written < cutoff) fs::remove(it->path(), fileError);
    }
}

// A new, empty file next to `path`: "<name>.tmp-XXXXXX", created exclusively.
bool createTemporary(const std::filesystem::path& path, std::filesystem::path& tmp,
                     std::string& error) {
    std::string pattern = path.string() + ".tmp-XXXXXX";
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) {
        error = "cannot create a temporary file in " +
                (path.has_parent_path() ? path.parent_path().string() : std::string(".")) + ": " +
                systemError(errno);
        return false;
    }
    ::close(fd);
    tmp = pattern;
    return true;
}

bool writeAll(const std::filesystem::path& path, std::string_view text, std::string& error) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) {
        error = "cannot open " + path.string() + " for writing: " + systemError(errno);
        return false;
    }
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error = "cannot write " + path.string() + ": " + systemError(n < 0 ? errno : EIO);
            ::close(fd);
            return false;
        }
        done += std::size_t(n);
    }
    if (::close(fd) != 0) {
        error = "cannot write " + path.string() + ": " + systemError(errno);
        return false;
    }
    return true;
}

// Links followed before a save gives up (Linux's own limit for one path lookup).
constexpr int kMaxLinkHops = 40;

} // namespace

std::optional<std::filesystem::path> saveTarget(const std::filesystem::path& path,
                                                std::string& error) {
    namespace fs = std::filesystem;
    fs::path current = path;
    for (int hop = 0; hop <= kMaxLinkHops; ++hop) {
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(current, ec);
        if (ec || !fs::is_symlink(status)) return current; // a file, a new name, or a folder
        const fs::path next = fs::read_symlink(current, ec);
        if (ec) {
            error = "cannot save " + path.string() + ": cannot read the symbolic link " +
                    current.string() + ": " + ec.message();
            return std::nullopt;
        }
        // A relative link is relative to the folder holding it. Not normalized: ".." after a
        // linked folder means what the system makes of it.
        current = next.is_absolute() ? next : current.parent_path() / next;
    }
    error = "cannot save " + path.string() + ": more than " + std::to_string(kMaxLinkHops) +
            " symbolic links in a row (a link loop?)";
    return std::nullopt;
}

std::filesystem::path backupPath(const std::filesystem::path& path) {
    std::filesystem::path backup = path;
    backup += ".bak";
    return backup;
}

bool replaceFileAtomically(
    const std::filesystem::path& path, bool keepBackup, std::string& error,
    const std::function<bool(const std::filesystem::path& tmp)>& writeTemporary) {
    error.clear();
    std::error_code ec;
    const std::optional<std::filesystem::path> resolved = saveTarget(path, error);
    if (!resolved) return false;
    const std::filesystem::path& target = *resolved;
    if (std::filesystem::is_directory(target, ec)) {
        error = "cannot save " + path.string() + ": it is a folder";
        return false;
    }
    if (target != path && target.has_parent_path() &&
        !std::filesystem::is_directory(target.parent_path(), ec)) {
        error = "cannot save " + path.string() + ": it is a symbolic link to " + target.string() +
                ", whose folder does not exist";
        return false;
    }
    removeStaleTemporaries(target);
    std::filesystem::path tmp;
    if (!createTemporary(target, tmp, error)) return false;
    const auto fail = [&](std::string why) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        error = std::move(why);
        return false;
    };
    if (!writeTemporary(tmp))
        return fail(error.empty() ? "cannot write " + tmp.string() : std::string(error));
    std::string why;
    if (!syncFile(tmp, why)) return fail(why);
    // mkstemp creates files readable by the owner only; give the saved file the permissions
    // an ordinary new file would get, or those of the file it replaces.
    const auto existing = std::filesystem::status(target, ec);
    const std::filesystem::perms perms =
        !ec && std::filesystem::exists(existing)
            ? existing.permissions()
            : std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                  std::filesystem::perms::group_read | std::filesystem::perms::others_read;
    std::filesystem::permissions(tmp, perms, ec);
    if (keepBackup && std::filesystem::exists(target, ec)) {
        // A hard link keeps the old file's bytes under the backup name without copying; a copy
        // is the fallback for file systems without links.
        const std::filesystem::path backup = backupPath(target);
        std::filesystem::remove(backup, ec);
        std::filesystem::create_hard_link(target, backup, ec);
        if (ec) {
            ec.clear();
            std::filesystem::copy_file(target, backup,
                                       std::filesystem::copy_options::overwrite_existing, ec);
        }
        if (ec)
            return fail("cannot keep the previous file as " + backup.string() + ": " +
                        ec.message());
    }
    if (::rename(tmp.c_str(), target.c_str()) != 0) {
        return fail("cannot replace " + target.string() + " with " + tmp.string() + ": " +
                    systemError(errno));
    }
    syncFolder(target.parent_path());
    return true;
}

bool saveTextFileAtomically(const std::filesystem::path& path, std::string_view text,
                            bool keepBackup, std::string& error) {
    return replaceFileAtomically(path, keepBackup, error, [&](const std::filesystem::path& tmp) {
        return writeAll(tmp, text, error);
    });
}

} // namespace rmsc
