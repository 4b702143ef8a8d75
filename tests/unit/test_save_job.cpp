// Saves written while the editing goes on (editor/save_job.hpp, Document::saveOf and ::saved):
// the document is clean where its history stood when the save was asked for, whatever was
// done meanwhile; a failed save changes nothing; one save at a time.
#include "editor/document.hpp"
#include "editor/save_job.hpp"
#include "editor/scene_edits.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace rmsc;
using namespace rmsc::editor;
namespace fs = std::filesystem;

namespace {

using SaveJobTest = rmsc::test::TempFolderTest;

void setExposure(Document& document, float exposure) {
    document.apply("Exposure", [=](Scene& s, Selection&) { s.render.exposure = exposure; });
}

// The exposure the file at `path` holds.
float savedExposure(const fs::path& path) {
    Diagnostics d;
    const std::optional<Scene> loaded = loadSceneForEditing(path, d);
    EXPECT_TRUE(loaded) << d.format();
    return loaded ? loaded->render.exposure : -1.0f;
}

} // namespace

TEST_F(SaveJobTest, TheDocumentIsCleanWhereItWasSavedWhateverWasEditedMeanwhile) {
    const fs::path path = folder_ / "scene.json";
    Document doc(emptyScene());
    setExposure(doc, 2.0f);
    const SceneSave save = doc.saveOf(path);
    setExposure(doc, 3.0f); // edited while the save is written
    std::string error;
    ASSERT_TRUE(writeSceneSave(save, error)) << error;
    EXPECT_EQ(savedExposure(path), 2.0f) << "the scene as it was when the save was asked for";
    doc.saved(save);
    EXPECT_EQ(doc.file(), path);
    EXPECT_TRUE(doc.dirty()) << "the edit since is not in the file";
    EXPECT_EQ(doc.scene().render.exposure, 3.0f) << "and is kept";
    doc.undo();
    EXPECT_FALSE(doc.dirty()) << "undone back to what the file holds";
    doc.redo();
    EXPECT_TRUE(doc.dirty());
}

TEST_F(SaveJobTest, AnEditOnAnotherBranchIsNotTakenForTheSavedOne) {
    const fs::path path = folder_ / "scene.json";
    Document doc(emptyScene());
    setExposure(doc, 2.0f);
    const SceneSave save = doc.saveOf(path);
    // Undone and edited again: the history has as many steps as when the save was asked for,
    // but the last is another.
    doc.undo();
    setExposure(doc, 4.0f);
    std::string error;
    ASSERT_TRUE(writeSceneSave(save, error)) << error;
    doc.saved(save);
    EXPECT_TRUE(doc.dirty()) << "exposure 4 is not what the file holds (2)";
    doc.undo();
    EXPECT_TRUE(doc.dirty()) << "nor is the scene before it: the saved step is gone";
}

TEST_F(SaveJobTest, ASaveOfASceneNoLongerOpenChangesNothing) {
    const fs::path path = folder_ / "scene.json";
    Document doc(emptyScene());
    setExposure(doc, 2.0f);
    const SceneSave save = doc.saveOf(path);
    doc.reset(emptyScene(), {}); // New, while the save is written
    setExposure(doc, 5.0f);
    std::string error;
    ASSERT_TRUE(writeSceneSave(save, error)) << error;
    doc.saved(save);
    EXPECT_TRUE(doc.file().empty()) << "the new scene has no file yet";
    EXPECT_TRUE(doc.dirty());
}

TEST_F(SaveJobTest, SavesOnTheWorkerOneAtATime) {
    const fs::path path = folder_ / "scene.json";
    Document doc(emptyScene());
    setExposure(doc, 2.0f);
    SaveJob job;
    EXPECT_FALSE(job.underWay());
    EXPECT_FALSE(job.take(true)) << "nothing to wait for";
    ASSERT_TRUE(job.start(doc.saveOf(path)));
    EXPECT_TRUE(job.underWay());
    EXPECT_FALSE(job.start(doc.saveOf(folder_ / "other.json"))) << "one at a time";
    std::optional<SaveOutcome> outcome = job.take(true);
    ASSERT_TRUE(outcome);
    EXPECT_TRUE(outcome->written) << outcome->error;
    EXPECT_FALSE(job.underWay());
    EXPECT_FALSE(job.take(true)) << "taken once";
    EXPECT_FALSE(fs::exists(folder_ / "other.json")) << "the refused save wrote nothing";
    doc.saved(outcome->save);
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(savedExposure(path), 2.0f);

    // Without waiting: polled until it is done, as the viewer's frames do.
    setExposure(doc, 3.0f);
    ASSERT_TRUE(job.start(doc.saveOf(path)));
    std::optional<SaveOutcome> polled;
    while (!(polled = job.take(false)))
        EXPECT_TRUE(job.underWay());
    EXPECT_TRUE(polled->written) << polled->error;
    EXPECT_EQ(savedExposure(path), 3.0f);
    EXPECT_NE(read(path.string() + ".bak").find("\"exposure\": 2"), std::string::npos)
        << "the file before it kept as the backup";
}

TEST_F(SaveJobTest, AFailedSaveSaysWhyAndChangesNothing) {
    const fs::path path = folder_ / "scene.json";
    Document doc(emptyScene());
    std::string error;
    ASSERT_TRUE(doc.saveAs(path, error)) << error;
    const std::string before = read(path);
    setExposure(doc, 5.0f);
    const fs::path blocked = folder_ / "blocked.json"; // a folder: cannot be replaced
    fs::create_directories(blocked);
    SaveJob job;
    ASSERT_TRUE(job.start(doc.saveOf(blocked)));
    const std::optional<SaveOutcome> outcome = job.take(true);
    ASSERT_TRUE(outcome);
    EXPECT_FALSE(outcome->written);
    EXPECT_NE(outcome->error.find("blocked.json"), std::string::npos) << outcome->error;
    // The viewer gives a failed save nothing back: the document is as it was.
    EXPECT_TRUE(doc.dirty());
    EXPECT_EQ(doc.file(), path);
    EXPECT_EQ(read(path), before);
}
