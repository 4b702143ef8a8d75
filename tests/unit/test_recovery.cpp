// Crash recovery files of the editor (editor/recovery.hpp): written from a document with
// unsaved edits, offered only while newer than the scene file, loading back the edited scene;
// not written for a scene that would not load.
#include "editor/document.hpp"
#include "editor/recovery.hpp"
#include "editor/recovery_job.hpp"
#include "editor/scene_edits.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <chrono>
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
    ASSERT_TRUE(writeRecovery(document.scene(), document.file(), error)) << error;
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
    EXPECT_FALSE(writeRecovery(document.scene(), document.file(), error));
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE(findRecovery(document.file()));
    std::filesystem::remove_all(dir);
}

// The recovery file follows the rule of a save: an invalid scene is not written (the recovery
// file of the last valid edits stays), and the error says where the scene is invalid.
TEST(Recovery, AnInvalidSceneIsNotWritten) {
    namespace fs = std::filesystem;
    const fs::path dir = freshFolder("invalid");
    Scene scene = emptyScene();
    SdfNode root = makeGroup(SdfOp::SmoothUnion);
    root.children = {makeShape(PrimitiveId::Sphere), makeShape(PrimitiveId::Box)};
    scene.sdf = root;
    Document document(scene, dir / "scene.json");
    std::string error;
    document.apply("Smoothness", [](Scene& s, Selection&) { s.sdf->smoothness = 0.5f; });
    ASSERT_TRUE(writeRecovery(document.scene(), document.file(), error)) << error;
    const std::string valid = [&] {
        std::ifstream in(recoveryPath(document.file()));
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();

    document.apply("Smoothness", [](Scene& s, Selection&) { s.sdf->smoothness = 0.0f; });
    EXPECT_FALSE(writeRecovery(document.scene(), document.file(), error));
    EXPECT_NE(error.find("/sdf/smoothness: expected a number >= 0.001, got 0"), std::string::npos)
        << error;
    std::ifstream in(recoveryPath(document.file()));
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), valid)
        << "the last valid recovery file stays";
    fs::remove_all(dir);
}

// The viewer's writer on a worker (editor/recovery_job.hpp): each outcome names its revision, a
// scene that does not pass a save's check is not written and says where, and after cancel() no
// write lands: the file removed then stays removed.
TEST(Recovery, TheJobWritesOnItsWorkerAndNothingLandsAfterACancel) {
    namespace fs = std::filesystem;
    const fs::path dir = freshFolder("job");
    const fs::path file = dir / "scene.json";
    Scene scene = emptyScene();
    scene.render.maxSteps = 77;
    RecoveryJob job;
    auto outcome = [&job] {
        for (int i = 0; i < 2000; ++i) {
            if (std::optional<RecoveryOutcome> o = job.take()) return o;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return std::optional<RecoveryOutcome>();
    };
    job.request(scene, file, 7);
    std::optional<RecoveryOutcome> written = outcome();
    ASSERT_TRUE(written);
    EXPECT_TRUE(written->written) << written->error;
    EXPECT_EQ(written->revision, 7u);
    Diagnostics diagnostics;
    std::optional<Scene> loaded = loadSceneForEditing(recoveryPath(file), diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.format();
    EXPECT_EQ(loaded->render.maxSteps, 77);

    SdfNode root = makeGroup(SdfOp::SmoothUnion);
    root.children = {makeShape(PrimitiveId::Sphere), makeShape(PrimitiveId::Box)};
    root.smoothness = 0.0f;
    scene.sdf = root;
    job.request(scene, file, 8);
    std::optional<RecoveryOutcome> refused = outcome();
    ASSERT_TRUE(refused);
    EXPECT_FALSE(refused->written);
    EXPECT_EQ(refused->revision, 8u);
    EXPECT_NE(refused->error.find("/sdf/smoothness"), std::string::npos) << refused->error;

    // Requests one after the other, then cancel and remove: whatever was under way finished
    // before the removal, and nothing is written after it.
    scene.sdf.reset();
    for (std::uint64_t revision = 9; revision < 14; ++revision)
        job.request(scene, file, revision);
    job.cancel();
    removeRecovery(file);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_FALSE(fs::exists(recoveryPath(file))) << "a write landed after the cancel";
    EXPECT_FALSE(job.take()) << "the cancelled writes' outcomes are dropped";
    fs::remove_all(dir);
}
