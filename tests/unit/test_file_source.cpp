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
    std::string longName(300, 'a');
    longName += ".json"; // (appended, not `+`: GCC 12 warns wrongly of -Warray-bounds on that)
    EXPECT_EQ(refusal(folder_ / longName), "file name too long");
}

TEST_F(FileSourceTest, RefusesFilesOverTheLimit) {
    std::ofstream(folder_ / "big.bin", std::ios::binary) << std::string(2000, 'y');
    EXPECT_NE(refusal(folder_ / "big.bin", 1999).find("2000 bytes, more than the limit of 1999"),
              std::string::npos);
    std::string error;
    EXPECT_TRUE(diskFileSource(2000).read(folder_ / "big.bin", error)) << error;
}

// resolveInside follows every symbolic link, the folder's too, before comparing: a link inside
// the folder that leads out of it is outside; one that stays inside, ".." that comes back and a
// missing file inside are inside.
TEST_F(FileSourceTest, ResolveInsideFollowsLinksBeforeComparing) {
    const fs::path a = folder_ / "a";
    fs::create_directories(a / "data");
    fs::create_directories(folder_ / "outside");
    std::ofstream(a / "data" / "x.bin") << "x";
    std::ofstream(folder_ / "outside" / "secret") << "s";
    fs::create_symlink("data/x.bin", a / "in.bin");
    fs::create_symlink(folder_ / "outside" / "secret", a / "out.bin");
    fs::create_symlink("../outside", a / "linked");
    fs::create_symlink(a, folder_ / "a_link");
    const fs::path real = fs::canonical(folder_);
    std::string why;
    EXPECT_EQ(resolveInside(a, a / "in.bin", why), real / "a" / "data" / "x.bin") << why;
    EXPECT_EQ(resolveInside(a, a / "data" / ".." / "in.bin", why), real / "a" / "data" / "x.bin");
    EXPECT_EQ(resolveInside(a, a / "missing" / "y.bin", why), real / "a" / "missing" / "y.bin");
    // The folder itself reached through a link: what counts is where it really is.
    EXPECT_EQ(resolveInside(folder_ / "a_link", a / "in.bin", why), real / "a" / "data" / "x.bin");

    EXPECT_FALSE(resolveInside(a, a / "out.bin", why));
    EXPECT_EQ(why, "resolves to " + (real / "outside" / "secret").string() + ", outside " +
                       (real / "a").string());
    EXPECT_FALSE(resolveInside(a, a / "linked" / "secret", why));
    EXPECT_NE(why.find("outside " + (real / "a").string()), std::string::npos) << why;
    EXPECT_FALSE(resolveInside(a, a / ".." / "outside" / "secret", why));
    // A sibling whose name starts like the folder's is not inside it.
    fs::create_directories(folder_ / "ab");
    std::ofstream(folder_ / "ab" / "z") << "z";
    EXPECT_FALSE(resolveInside(a, folder_ / "ab" / "z", why));
}

// The disk source holds readInside to the folder and, with a sandbox, every read to the
// sandbox; the refusal says which rule. Links that stay inside still read.
TEST_F(FileSourceTest, DiskReadsStayInsideTheirFolderAndTheSandbox) {
    const fs::path box = folder_ / "box";
    fs::create_directories(box / "model");
    fs::create_directories(folder_ / "outside");
    std::ofstream(box / "model" / "buffer.bin") << "inside";
    std::ofstream(box / "scene.json") << "scene";
    std::ofstream(folder_ / "outside" / "secret") << "secret";
    fs::create_symlink(folder_ / "outside" / "secret", box / "model" / "escape.bin");
    fs::create_symlink("buffer.bin", box / "model" / "alias.bin");
    fs::create_symlink(box / "scene.json", box / "model" / "up.bin");
    const std::string outside = (fs::canonical(folder_) / "outside" / "secret").string();

    std::string error;
    const FileSource free = diskFileSource();
    EXPECT_EQ(free.read(box / "model" / "escape.bin", error), "secret"); // scene-level: anywhere
    EXPECT_EQ(readInsideFolder(free, box / "model", "alias.bin", error), "inside") << error;
    EXPECT_FALSE(readInsideFolder(free, box / "model", "escape.bin", error));
    EXPECT_NE(error.find("resolves to " + outside + ", outside "), std::string::npos) << error;
    EXPECT_NE(error.find("its URIs must stay inside that folder"), std::string::npos) << error;
    EXPECT_FALSE(
        readInsideFolder(free, box / "model", "up.bin", error)); // in the box, not the folder

    const FileSource boxed = diskFileSource(1 << 20, box);
    EXPECT_EQ(boxed.read(box / "scene.json", error), "scene") << error;
    EXPECT_EQ(boxed.read(box / "model" / "up.bin", error), "scene") << error;
    EXPECT_FALSE(boxed.read(box / "model" / "escape.bin", error));
    EXPECT_NE(error.find("resolves to " + outside + ", outside " + fs::canonical(box).string()),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("the --sandbox folder"), std::string::npos) << error;
    EXPECT_FALSE(boxed.read(box / ".." / "outside" / "secret", error));
    EXPECT_NE(error.find("the --sandbox folder"), std::string::npos) << error;
    EXPECT_EQ(readInsideFolder(boxed, box / "model", "alias.bin", error), "inside") << error;
    // A missing file inside the sandbox is simply missing.
    EXPECT_FALSE(boxed.read(box / "missing.json", error));
    EXPECT_EQ(error, "file not found");

    // Read as bytes (glTF buffers), under the same rules.
    std::vector<unsigned char> bytes;
    ASSERT_TRUE(free.readInsideBytes);
    EXPECT_TRUE(readInsideFolderBytes(free, box / "model", "alias.bin", bytes, error)) << error;
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "inside");
    EXPECT_FALSE(readInsideFolderBytes(free, box / "model", "escape.bin", bytes, error));
    EXPECT_NE(error.find("its URIs must stay inside that folder"), std::string::npos) << error;
    EXPECT_FALSE(readInsideFolderBytes(boxed, box / "model", "up.bin", bytes, error));
}

// Sources without links (in memory, embedded) read folder / relative: the lexical rule of
// gltf::resolveInFolder is all they need.
TEST(FileSourceInside, SourcesWithoutLinksReadTheJoinedPath) {
    FileSource memory;
    memory.read = [](const fs::path& path, std::string&) -> std::optional<std::string> {
        return path.generic_string();
    };
    std::string error;
    EXPECT_EQ(readInsideFolder(memory, "assets", "data/a.bin", error), "assets/data/a.bin");
    std::vector<unsigned char> bytes;
    EXPECT_TRUE(readInsideFolderBytes(memory, "assets", "data/a.bin", bytes, error));
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "assets/data/a.bin");
}
