// Reading input files from disk (core/file_source.hpp): regular files only, each under the size
// limit, and every refusal in words: FIFOs, devices and folders are refused before a byte is
// read (and without blocking), link loops and overlong names are told apart from missing files.
#include "core/file_source.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace rmsc;
namespace fs = std::filesystem;

namespace {

class FileSourceTest : public test::TempFolderTest {
  protected:
    std::string refusal(const fs::path& path, std::uintmax_t maxBytes = 1 << 20) {
        std::string error;
        const std::optional<std::string> bytes = diskFileSource(maxBytes).read(path, error);
        EXPECT_FALSE(bytes.has_value()) << path;
        return error;
    }
};

} // namespace

TEST_F(FileSourceTest, ReadsARegularFileWhole) {
    std::string content(100000, 'x');
    content[5] = '\0';
    std::ofstream(folder_ / "a.json", std::ios::binary) << content;
    std::string error;
    const std::optional<std::string> bytes = diskFileSource().read(folder_ / "a.json", error);
    ASSERT_TRUE(bytes) << error;
    EXPECT_EQ(*bytes, content);
    // Through a symbolic link too.
    fs::create_symlink(folder_ / "a.json", folder_ / "link.json");
    EXPECT_EQ(diskFileSource().read(folder_ / "link.json", error), content);
}

TEST_F(FileSourceTest, RefusesWhatIsNotARegularFileWithoutBlocking) {
    ASSERT_EQ(::mkfifo((folder_ / "fifo.json").c_str(), 0600), 0);
    EXPECT_NE(refusal(folder_ / "fifo.json").find("not a regular file"), std::string::npos);
    EXPECT_NE(refusal("/dev/zero").find("not a regular file"), std::string::npos);
    EXPECT_NE(refusal(folder_).find("is a directory"), std::string::npos);
}

TEST_F(FileSourceTest, NamesWhyAPathCannotBeOpened) {
    EXPECT_EQ(refusal(folder_ / "missing.json"), "file not found");
    fs::create_symlink(folder_ / "loop2", folder_ / "loop1");
    fs::create_symlink(folder_ / "loop1", folder_ / "loop2");
    EXPECT_NE(refusal(folder_ / "loop1").find("symbolic links"), std::string::npos);
    EXPECT_EQ(refusal(folder_ / (std::string(300, 'a') + ".json")), "file name too long");
}

TEST_F(FileSourceTest, RefusesFilesOverTheLimit) {
    std::ofstream(folder_ / "big.bin", std::ios::binary) << std::string(2000, 'y');
    EXPECT_NE(refusal(folder_ / "big.bin", 1999).find("2000 bytes, more than the limit of 1999"),
              std::string::npos);
    std::string error;
    EXPECT_TRUE(diskFileSource(2000).read(folder_ / "big.bin", error)) << error;
}
