// FileSource implementations: the disk and the files embedded in the binary, and confinement of
// disk reads to folders (symbolic links resolved).
#include "core/file_source.hpp"

#include "core/embedded.hpp"

#include <cerrno>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rmsc {

namespace {

// Why a path cannot be read, in words a user acts on.
std::string openError(int error) {
    switch (error) {
    case ENOENT:
    case ENOTDIR:
        return "file not found";
    case ELOOP:
        return "too many levels of symbolic links (a link loop?)";
    case ENAMETOOLONG:
        return "file name too long";
    case EACCES:
        return "permission denied";
    default:
        return "cannot open file for reading: " + std::generic_category().message(error);
    }
}

// A folder reads must stay inside (resolved), and the rule that says so, for messages.
struct Confinement {
    std::filesystem::path folder;
    const char* rule;
};

constexpr const char* kSandboxRule =
    " (the --sandbox folder: every file a scene reads must be inside it)";
constexpr const char* kFolderRule =
    " (the folder of the file that names it: its URIs must stay inside that folder)";

// `path` made absolute, with every symbolic link of its existing part resolved.
std::optional<std::filesystem::path> resolvedPath(const std::filesystem::path& path,
                                                  std::string& why) {
    std::error_code ec;
    std::filesystem::path out = std::filesystem::absolute(path.empty() ? "." : path, ec);
    if (!ec) out = std::filesystem::weakly_canonical(out, ec);
    if (ec) {
        why = openError(ec.value());
        return std::nullopt;
    }
    return out;
}

// Whether the absolute, resolved `target` is `folder` or below it (compared by components).
bool isInside(const std::filesystem::path& folder, const std::filesystem::path& target) {
    auto at = target.begin();
    for (const std::filesystem::path& part : folder) {
        if (part.empty()) continue; // a trailing separator
        if (at == target.end() || *at != part) return false;
        ++at;
    }
    return true;
}

// The file an open descriptor refers to, where the system says (/proc on Linux).
std::optional<std::filesystem::path> openedFile(int fd) {
    std::error_code ec;
    std::filesystem::path path =
        std::filesystem::read_symlink("/proc/self/fd/" + std::to_string(fd), ec);
    if (ec || !path.is_absolute()) return std::nullopt;
    return path;
}

// Reads all of a regular file of at most maxBytes. The file is opened without blocking (a FIFO
// would otherwise block the open forever) and checked on the open descriptor, so what is read
// is what was checked: devices, FIFOs and sockets are refused before a byte is read, and a file
// that grows while being read is refused at maxBytes. The opened file must lie inside every
// folder of `confinements` (checked where the system tells which file was opened: a link
// changed between the caller's check and the open is caught here).
// Bytes: std::string or std::vector<unsigned char>, read into directly (no copy).
template <class Bytes>
std::optional<Bytes> readRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes,
                                     const std::vector<Confinement>& confinements,
                                     std::string& error) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        error = openError(errno);
        return std::nullopt;
    }
    struct FileCloser {
        int fd;
        ~FileCloser() { ::close(fd); }
    } closer{fd};
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        error = openError(errno);
        return std::nullopt;
    }
    if (S_ISDIR(info.st_mode)) {
        error = "is a directory, expected a file";
        return std::nullopt;
    }
    if (!S_ISREG(info.st_mode)) {
        error = "is not a regular file (a device, FIFO or socket), expected a file";
        return std::nullopt;
    }
    if (!confinements.empty()) {
        if (const std::optional<std::filesystem::path> opened = openedFile(fd)) {
            for (const Confinement& c : confinements) {
                if (!isInside(c.folder, *opened)) {
                    error = "resolves to " + opened->string() + ", outside " + c.folder.string() +
                            c.rule;
                    return std::nullopt;
                }
            }
        }
    }
    if (std::uintmax_t(info.st_size) > maxBytes) {
        error = "file is " + std::to_string(info.st_size) + " bytes, more than the limit of " +
                std::to_string(maxBytes);
        return std::nullopt;
    }
    Bytes bytes;
    bytes.resize(std::size_t(info.st_size));
    std::size_t done = 0;
    char chunk[65536];
    for (;;) {
        char* target = done < bytes.size() ? reinterpret_cast<char*>(bytes.data()) + done : chunk;
        const std::size_t room = done < bytes.size() ? bytes.size() - done : sizeof chunk;
        const ssize_t n = ::read(fd, target, room);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = "read error: " + std::generic_category().message(errno);
            return std::nullopt;
        }
        if (n == 0) break;
        if (target == chunk) bytes.insert(bytes.end(), chunk, chunk + n); // the file grew
        done += std::size_t(n);
        if (done > maxBytes) {
            error = "file grew past the limit of " + std::to_string(maxBytes) +
                    " bytes while being read";
            return std::nullopt;
        }
    }
    bytes.resize(done); // it may have shrunk
    return bytes;
}

// Reads `path` if it resolves inside every folder of `confinements`, checked before opening
// it (so nothing outside is even opened) and on the opened file.
template <class Bytes = std::string>
std::optional<Bytes> readConfined(const std::filesystem::path& path, std::uintmax_t maxBytes,
                                  const std::vector<Confinement>& confinements,
                                  std::string& error) {
    if (confinements.empty()) return readRegularFile<Bytes>(path, maxBytes, confinements, error);
    const std::optional<std::filesystem::path> target = resolvedPath(path, error);
    if (!target) return std::nullopt;
    for (const Confinement& c : confinements) {
        if (!isInside(c.folder, *target)) {
            error = "resolves to " + target->string() + ", outside " + c.folder.string() + c.rule;
            return std::nullopt;
        }
    }
    return readRegularFile<Bytes>(*target, maxBytes, confinements, error);
}

std::filesystem::path& sandboxFolder() {
    static std::filesystem::path folder;
    return folder;
}

} // namespace

void setDiskReadSandbox(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::path resolved;
    if (!folder.empty()) resolved = std::filesystem::canonical(folder, ec);
    if (ec) resolved = std::filesystem::absolute(folder, ec).lexically_normal();
    sandboxFolder() = resolved;
}

const std::filesystem::path& diskReadSandbox() {
    return sandboxFolder();
}

std::optional<std::string> readInsideFolder(const FileSource& source,
                                            const std::filesystem::path& folder,
                                            const std::filesystem::path& relative,
                                            std::string& error) {
    if (source.readInside) return source.readInside(folder, relative, error);
    return source.read(folder / relative, error);
}

bool readInsideFolderBytes(const FileSource& source, const std::filesystem::path& folder,
                           const std::filesystem::path& relative, std::vector<unsigned char>& out,
                           std::string& error) {
    if (source.readInsideBytes) return source.readInsideBytes(folder, relative, out, error);
    const std::optional<std::string> bytes = readInsideFolder(source, folder, relative, error);
    if (!bytes) return false;
    out.assign(bytes->begin(), bytes->end());
    return true;
}

std::optional<std::filesystem::path> resolveInside(const std::filesystem::path& folder,
                                                   const std::filesystem::path& path,
                                                   std::string& why) {
    const std::optional<std::filesystem::path> base = resolvedPath(folder, why);
    if (!base) return std::nullopt;
    std::optional<std::filesystem::path> target = resolvedPath(path, why);
    if (target && !isInside(*base, *target)) {
        why = "resolves to " + target->string() + ", outside " + base->string();
        return std::nullopt;
    }
    return target;
}

FileSource diskFileSource(std::uintmax_t maxBytes, const std::filesystem::path& sandbox) {
    std::vector<Confinement> confinements;
    if (!sandbox.empty()) {
        std::string ignored;
        confinements.push_back({resolvedPath(sandbox, ignored).value_or(sandbox), kSandboxRule});
    }
    FileSource source;
    source.read = [maxBytes, confinements](const std::filesystem::path& path,
                                           std::string& error) -> std::optional<std::string> {
        return readConfined(path, maxBytes, confinements, error);
    };
    source.readInside = [maxBytes, confinements](const std::filesystem::path& folder,
                                                 const std::filesystem::path& relative,
                                                 std::string& error) -> std::optional<std::string> {
        const std::optional<std::filesystem::path> resolved = resolvedPath(folder, error);
        if (!resolved) return std::nullopt;
        std::vector<Confinement> inside = confinements;
        inside.insert(inside.begin(), {*resolved, kFolderRule});
        return readConfined(*resolved / relative, maxBytes, inside, error);
    };
    source.readInsideBytes = [maxBytes, confinements](const std::filesystem::path& folder,
                                                      const std::filesystem::path& relative,
                                                      std::vector<unsigned char>& out,
                                                      std::string& error) {
        const std::optional<std::filesystem::path> resolved = resolvedPath(folder, error);
        if (!resolved) return false;
        std::vector<Confinement> inside = confinements;
        inside.insert(inside.begin(), {*resolved, kFolderRule});
        std::optional<std::vector<unsigned char>> bytes =
            readConfined<std::vector<unsigned char>>(*resolved / relative, maxBytes, inside, error);
        if (!bytes) return false;
        out = std::move(*bytes);
        return true;
    };
    return source;
}

FileSource embeddedFileSource() {
    return {
        [](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
            const std::string key = path.lexically_normal().generic_string();
            for (const EmbeddedFile& f : embeddedSamples())
                if (f.path == key) return std::string(f.data);
            error = "not among the files built into rmsc";
            return std::nullopt;
        }};
}

} // namespace rmsc
