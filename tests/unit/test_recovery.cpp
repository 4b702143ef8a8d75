// Crash recovery files of the editor (editor/recovery.hpp): written from a document with
// unsaved edits, offered only while newer than the scene file, loading back the edited scene.
#include "editor/recovery.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

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

TEST(Recovery, UnsavedEditsComeBackUntilTheSceneIsSaved) {
    const std::filesystem::path dir = freshFolder("offer");
    const std::filesystem::path file = dir / "scene.json";
    Document document(emptyScene(), {});
    std::string error;
    ASSERT_TRUE(document.saveAs(file, error)) << error;
    EXPECT_FALSE(findRecovery(file)) << "a saved scene has nothing to recover";

    // Make sure the recovery file's time is later than the scene's on coarse clocks.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    document.apply("Edit", [](Scene& scene, Selection&) { scene.render.maxSteps = 77; });
    ASSERT_TRUE(document.dirty());
    ASSERT_TRUE(writeRecovery(document, error)) << error;
    const std::optional<std::filesystem::path> offered = findRecovery(file);
    ASSERT_TRUE(offered);
    EXPECT_EQ(*offered, recoveryPath(file));
    EXPECT_EQ(offered->parent_path(), dir) << "kept next to the scene";
    EXPECT_NE(offered->extension(), ".json") << "not picked up as a scene by *.json globs";

    Diagnostics diagnostics;
    const std::optional<Scene> recovered = loadSceneForEditing(*offered, diagnostics);
    ASSERT_TRUE(recovered) << diagnostics.format();
    EXPECT_EQ(recovered->render.maxSteps, 77);

    // Saving afterwards makes the recovery stale: not offered, even if not yet removed.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_TRUE(document.save(error)) << error;
    EXPECT_FALSE(findRecovery(file));
    removeRecovery(file);
    EXPECT_FALSE(std::filesystem::exists(recoveryPath(file)));
    std::filesystem::remove_all(dir);
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
