// Crash recovery files of the editor (editor/recovery.hpp): written from a document with
// unsaved edits, offered only while newer than the scene file, loading back the edited scene.
#include "editor/recovery.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("rmsc-recovery-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

// findRecovery compares the files' modification times. The test sets them (the scene an hour
// ago, the recovery then and a minute later) rather than waiting for the clock to move, so it
// holds on any clock resolution.
TEST(Recovery, UnsavedEditsComeBackUntilTheSceneIsSaved) {
    namespace fs = std::filesystem;
    const fs::path dir = freshFolder("offer");
    const fs::path file = dir / "scene.json";
    const fs::file_time_type savedAt = fs::file_time_type::clock::now() - std::chrono::hours(1);
    Document document(emptyScene(), {});
    std::string error;
    ASSERT_TRUE(document.saveAs(file, error)) << error;
    fs::last_write_time(file, savedAt);
    EXPECT_FALSE(findRecovery(file)) << "a saved scene has nothing to recover";

    document.apply("Edit", [](Scene& scene, Selection&) { scene.render.maxSteps = 77; });
    ASSERT_TRUE(document.dirty());
    ASSERT_TRUE(writeRecovery(document, error)) << error;
    // Written at the same time as the scene: not newer, so not offered.
    fs::last_write_time(recoveryPath(file), savedAt);
    EXPECT_FALSE(findRecovery(file)) << "offered, but not newer than the scene";
    fs::last_write_time(recoveryPath(file), savedAt + std::chrono::minutes(1));
    const std::optional<fs::path> offered = findRecovery(file);
    ASSERT_TRUE(offered);
    EXPECT_EQ(*offered, recoveryPath(file));
    EXPECT_EQ(offered->parent_path(), dir) << "kept next to the scene";
    EXPECT_NE(offered->extension(), ".json") << "not picked up as a scene by *.json globs";

    Diagnostics diagnostics;
    const std::optional<Scene> recovered = loadSceneForEditing(*offered, diagnostics);
    ASSERT_TRUE(recovered) << diagnostics.format();
    EXPECT_EQ(recovered->render.maxSteps, 77);

    // Saving afterwards makes the recovery stale: not offered, even if not yet removed. The save
    // writes the scene now, an hour after the recovery's time.
    ASSERT_TRUE(document.save(error)) << error;
    EXPECT_FALSE(findRecovery(file));
    removeRecovery(file);
    EXPECT_FALSE(fs::exists(recoveryPath(file)));
    fs::remove_all(dir);
}

TEST(Recovery, AnUnwritableFolderIsReportedNotThrown) {
    const std::filesystem::path dir = freshFolder("unwritable");
    Document document(emptyScene(), dir / "missing-folder" / "scene.json");
    std::string error;
    EXPECT_FALSE(writeRecovery(document, error));
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE(findRecovery(document.file()));
    std::filesystem::remove_all(dir);
}
