// FileSource implementations: the disk and the files embedded in the binary.
#include "core/file_source.hpp"

#include "core/embedded.hpp"

#include <cerrno>
#include <string>
#include <system_error>

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

// Reads all of a regular file of at most maxBytes. The file is opened without blocking (a FIFO
// would otherwise block the open forever) and checked on the open descriptor, so what is read
// is what was checked: devices, FIFOs and sockets are refused before a byte is read, and a file
// that grows while being read is refused at maxBytes.
std::optional<std::string> readRegularFile(const std::filesystem::path& path,
                                           std::uintmax_t maxBytes, std::string& error) {
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
    if (std::uintmax_t(info.st_size) > maxBytes) {
        error = "file is " + std::to_string(info.st_size) + " bytes, more than the limit of " +
                std::to_string(maxBytes);
        return std::nullopt;
    }
    std::string bytes;
    bytes.resize(std::size_t(info.st_size));
    std::size_t done = 0;
    char chunk[65536];
    for (;;) {
        char* target = done < bytes.size() ? bytes.data() + done : chunk;
        const std::size_t room = done < bytes.size() ? bytes.size() - done : sizeof chunk;
        const ssize_t n = ::read(fd, target, room);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = "read error: " + std::generic_category().message(errno);
            return std::nullopt;
        }
        if (n == 0) break;
        if (target == chunk) bytes.append(chunk, std::size_t(n)); // the file grew
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

} // namespace

FileSource diskFileSource(std::uintmax_t maxBytes) {
    return {[maxBytes](const std::filesystem::path& path,
                       std::string& error) -> std::optional<std::string> {
        return readRegularFile(path, maxBytes, error);
    }};
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
