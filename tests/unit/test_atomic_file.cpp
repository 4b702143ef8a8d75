// Atomic saves (core/atomic_file.hpp): the new content replaces the old in one step, the
// previous content is kept as <name>.bak, and a failed save reports why and leaves the old
// file and the folder as they were.
#include "core/atomic_file.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace rmsc;
namespace fs = std::filesystem;

namespace {

// A fresh, empty folder per test, removed afterwards.
class AtomicFile : public test::TempFolderTest {
  protected:
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& entry : fs::directory_iterator(folder_))
            out.push_back(entry.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }
};

} // namespace

TEST_F(AtomicFile, NewFileIsWrittenWithoutBackupOrTemporary) {
    std::string error;
    ASSERT_TRUE(saveTextFileAtomically(folder_ / "scene.json", "{\"version\": 1}\n", true, error))
        << error;
    EXPECT_EQ(read(folder_ / "scene.json"), "{\"version\": 1}\n");
    EXPECT_EQ(names(), std::vector<std::string>{"scene.json"});
    // Ordinary permissions, not mkstemp's owner-only ones.
    const auto perms = fs::status(folder_ / "scene.json").permissions();
    EXPECT_NE(perms & fs::perms::others_read, fs::perms::none);
}

TEST_F(AtomicFile, BackupHoldsThePreviousContent) {
    write(folder_ / "scene.json", "old");
    std::string error;
    ASSERT_TRUE(saveTextFileAtomically(folder_ / "scene.json", "new", true, error)) << error;
    EXPECT_EQ(read(folder_ / "scene.json"), "new");
    EXPECT_EQ(read(folder_ / "scene.json.bak"), "old");
    // A second save moves the backup on: it always holds the content before the last save.
    ASSERT_TRUE(saveTextFileAtomically(folder_ / "scene.json", "newer", true, error)) << error;
    EXPECT_EQ(read(folder_ / "scene.json"), "newer");
    EXPECT_EQ(read(folder_ / "scene.json.bak"), "new");
    EXPECT_EQ(names(), (std::vector<std::string>{"scene.json", "scene.json.bak"}));
}

TEST_F(AtomicFile, WithoutBackupNoBakFileAppears) {
    write(folder_ / "a.txt", "old");
    std::string error;
    ASSERT_TRUE(saveTextFileAtomically(folder_ / "a.txt", "new", false, error)) << error;
    EXPECT_EQ(read(folder_ / "a.txt"), "new");
    EXPECT_EQ(names(), std::vector<std::string>{"a.txt"});
}

TEST_F(AtomicFile, ParentThatIsAFileFailsWithAReason) {
    write(folder_ / "not_a_folder", "x");
    std::string error;
    EXPECT_FALSE(
        saveTextFileAtomically(folder_ / "not_a_folder" / "scene.json", "new", true, error));
    EXPECT_NE(error.find("not_a_folder"), std::string::npos) << error;
    EXPECT_NE(error.find("Not a directory"), std::string::npos) << error;
    EXPECT_EQ(read(folder_ / "not_a_folder"), "x");
    EXPECT_EQ(names(), std::vector<std::string>{"not_a_folder"});
}

TEST_F(AtomicFile, MissingFolderFailsWithAReason) {
    std::string error;
    EXPECT_FALSE(saveTextFileAtomically(folder_ / "missing" / "scene.json", "new", true, error));
    EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

TEST_F(AtomicFile, FolderInTheWayFailsAndIsLeftAlone) {
    fs::create_directory(folder_ / "scene.json");
    std::string error;
    EXPECT_FALSE(saveTextFileAtomically(folder_ / "scene.json", "new", true, error));
    EXPECT_NE(error.find("is a folder"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_directory(folder_ / "scene.json"));
}

TEST_F(AtomicFile, FailedWriteLeavesTheOldFileAndNoTemporary) {
    write(folder_ / "image.png", "old image");
    write(folder_ / "image.png.bak", "older image");
    std::string error;
    fs::path temporary;
    const bool saved =
        replaceFileAtomically(folder_ / "image.png", true, error, [&](const fs::path& tmp) {
            temporary = tmp;
            std::ofstream(tmp, std::ios::binary) << "half an ima"; // then the disk is full
            return false;
        });
    EXPECT_FALSE(saved);
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(temporary.parent_path(), folder_); // the temporary was in the same folder
    EXPECT_EQ(read(folder_ / "image.png"), "old image");
    EXPECT_EQ(read(folder_ / "image.png.bak"), "older image"); // backup untouched too
    EXPECT_EQ(names(), (std::vector<std::string>{"image.png", "image.png.bak"}));
}

TEST_F(AtomicFile, ReadOnlyFolderFailsAndKeepsTheOldFile) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
    write(folder_ / "scene.json", "old");
    fs::permissions(folder_, fs::perms::owner_read | fs::perms::owner_exec);
    std::string error;
    const bool saved = saveTextFileAtomically(folder_ / "scene.json", "new", true, error);
    fs::permissions(folder_, fs::perms::owner_all);
    EXPECT_FALSE(saved);
    EXPECT_NE(error.find("Permission denied"), std::string::npos) << error;
    EXPECT_EQ(read(folder_ / "scene.json"), "old");
    EXPECT_EQ(names(), std::vector<std::string>{"scene.json"});
}

// A save that was killed leaves "<name>.tmp-XXXXXX" behind; the next save of that file removes
// such leftovers once they are old (an hour), and leaves young ones (a save running in another
// process) and other files alone.
TEST_F(AtomicFile, StaleTemporariesOfEarlierSavesAreRemoved) {
    const fs::path path = folder_ / "scene.json";
    const fs::path stale = folder_ / "scene.json.tmp-Ab12Cd";
    const fs::path young = folder_ / "scene.json.tmp-Zz99Yy";
    const fs::path other = folder_ / "other.json.tmp-Ab12Cd";
    const fs::path similar = folder_ / "scene.json.tmp-toolong";
    for (const fs::path& p : {stale, young, other, similar})
        std::ofstream(p) << "leftover";
    const auto twoHoursAgo = fs::file_time_type::clock::now() - std::chrono::hours(2);
    for (const fs::path& p : {stale, other, similar})
        fs::last_write_time(p, twoHoursAgo);
    std::string error;
    ASSERT_TRUE(saveTextFileAtomically(path, "new", false, error)) << error;
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(young));
    EXPECT_TRUE(fs::exists(other));
    EXPECT_TRUE(fs::exists(similar));
    EXPECT_EQ(read(path), "new");
}

// Saving to a symbolic link writes the file it points to, as editors do: the link stays a link
// to the same file, which gets the new content, and the backup is a real file beside it.
TEST_F(AtomicFile, SaveThroughALinkReplacesItsTargetAndKeepsTheLink) {
    write(folder_ / "real.json", "old");
    fs::create_symlink("real.json", folder_ / "scene.json");
    std::string error;
    ASSERT_TRUE(saveTextFileAtomically(folder_ / "scene.json", "new", true, error)) << error;
    ASSERT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "scene.json")));
    EXPECT_EQ(fs::read_symlink(folder_ / "scene.json"), fs::path("real.json"));
    EXPECT_EQ(read(folder_ / "real.json"), "new");
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(folder_ / "real.json.bak")));
    EXPECT_EQ(read(folder_ / "real.json.bak"), "old");
    EXPECT_EQ(names(), (std::vector<std::string>{"real.json", "real.json.bak", "scene.json"}));
}

// A chain of relative links across folders: each resolves against its own folder, and the
// temporary file is made next to the final target (so the rename stays in one folder).
TEST_F(AtomicFile, ChainOfLinksIsFollowedToTheEnd) {
    fs::create_directories(folder_ / "a");
    fs::create_directories(folder_ / "b");
    write(folder_ / "b" / "image.png", "old image");
    fs::create_symlink("image.png", folder_ / "b" / "latest.png");
    fs::create_symlink("../b/latest.png", folder_ / "a" / "out.png");
    std::string error;
    fs::path temporary;
    ASSERT_TRUE(replaceFileAtomically(folder_ / "a" / "out.png", false, error,
                                      [&](const fs::path& tmp) {
                                          temporary = tmp;
                                          std::ofstream(tmp, std::ios::binary) << "new image";
                                          return true;
                                      }))
        << error;
    EXPECT_EQ(fs::canonical(temporary.parent_path()), fs::canonical(folder_ / "b"));
    EXPECT_EQ(read(folder_ / "b" / "image.png"), "new image");
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "a" / "out.png")));
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "b" / "latest.png")));
    EXPECT_EQ(fs::directory_iterator(folder_ / "a")->path().filename(), "out.png");
}

// A dangling link whose target's folder exists creates the target; one whose folder is missing
// is refused and left alone; a loop of links is refused.
TEST_F(AtomicFile, DanglingLinksAndLinkLoops) {
    fs::create_symlink("made.json", folder_ / "dangling.json");
    std::string error;
    ASSERT_TRUE(saveTextFileAtomically(folder_ / "dangling.json", "new", true, error)) << error;
    EXPECT_EQ(read(folder_ / "made.json"), "new");
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "dangling.json")));

    fs::create_symlink("gone/x.json", folder_ / "nowhere.json");
    EXPECT_FALSE(saveTextFileAtomically(folder_ / "nowhere.json", "new", true, error));
    EXPECT_NE(error.find("nowhere.json"), std::string::npos) << error;
    EXPECT_NE(error.find("whose folder does not exist"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "nowhere.json")));

    fs::create_symlink("loop_b", folder_ / "loop_a");
    fs::create_symlink("loop_a", folder_ / "loop_b");
    EXPECT_FALSE(saveTextFileAtomically(folder_ / "loop_a", "new", true, error));
    EXPECT_NE(error.find("a link loop?"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "loop_a")));
    EXPECT_EQ(names(), (std::vector<std::string>{"dangling.json", "loop_a", "loop_b", "made.json",
                                                 "nowhere.json"}));
}
