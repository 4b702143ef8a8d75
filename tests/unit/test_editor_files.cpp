// The viewer's file handling without a window: the file browser's filters and listings
// (editor/file_browser.hpp), the recent files (editor/recent_files.hpp) and what a file dropped
// on the window does (editor/dropped_files.hpp).
#include "editor/dropped_files.hpp"
#include "editor/file_browser.hpp"
#include "editor/recent_files.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace rmsc;
using namespace rmsc::editor;

namespace {

class ViewerFiles : public ::testing::Test {
  protected:
    fs::path folder;
    void SetUp() override {
        folder = fs::temp_directory_path() /
                 ("rmsc-files-" + std::to_string(::getpid()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder);
        fs::create_directories(folder);
    }
    void TearDown() override { fs::remove_all(folder); }
    void write(const fs::path& path, const std::string& text) {
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
    }
    std::string read(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }
};

std::vector<std::string> names(const DirectoryListing& listing) {
    std::vector<std::string> out;
    for (const DirectoryEntry& e : listing.entries)
        out.push_back(e.folder ? e.name + "/" : e.name);
    return out;
}

} // namespace

TEST_F(ViewerFiles, FiltersByUse) {
    EXPECT_TRUE(matchesFileKind("a/scene.json", FileKind::Scene));
    EXPECT_TRUE(matchesFileKind("SCENE.JSON", FileKind::Scene)) << "any case";
    EXPECT_FALSE(matchesFileKind("scene.json.bak", FileKind::Scene));
    EXPECT_TRUE(matchesFileKind("m.glb", FileKind::Mesh));
    EXPECT_TRUE(matchesFileKind("m.gltf", FileKind::Mesh));
    EXPECT_FALSE(matchesFileKind("m.obj", FileKind::Mesh));
    EXPECT_TRUE(matchesFileKind("t.JPeg", FileKind::Texture));
    EXPECT_FALSE(matchesFileKind("sky.hdr", FileKind::Texture)) << "textures are PNG or JPEG";
    EXPECT_TRUE(matchesFileKind("sky.hdr", FileKind::Sky));
    EXPECT_NE(fileKindLabel(FileKind::Mesh).find(".glb"), std::string_view::npos);
}

TEST_F(ViewerFiles, ListsFoldersThenMatchingFilesByName) {
    write(folder / "b.json", "{}");
    write(folder / "A.json", "{}");
    write(folder / "c.gltf", "{}");
    write(folder / ".hidden.json", "{}");
    write(folder / "notes.txt", "x");
    write(folder / "zoo" / "x.json", "{}");
    write(folder / "Assets" / "y.png", "");
    const DirectoryListing scenes = listDirectory(folder, FileKind::Scene);
    EXPECT_EQ(scenes.error, "");
    EXPECT_EQ(names(scenes), (std::vector<std::string>{"Assets/", "zoo/", "A.json", "b.json"}));
    EXPECT_EQ(scenes.entries[2].bytes, 2u);
    EXPECT_EQ(names(listDirectory(folder, FileKind::Mesh)),
              (std::vector<std::string>{"Assets/", "zoo/", "c.gltf"}));
    EXPECT_EQ(
        names(listDirectory(folder, FileKind::Mesh, true)),
        (std::vector<std::string>{"Assets/", "zoo/", "A.json", "b.json", "c.gltf", "notes.txt"}))
        << "all files, hidden ones still left out";
    const DirectoryListing missing = listDirectory(folder / "nope", FileKind::Scene);
    EXPECT_TRUE(missing.entries.empty());
    EXPECT_NE(missing.error.find("nope"), std::string::npos) << missing.error;
}

TEST_F(ViewerFiles, TypedNamesAndFieldText) {
    EXPECT_EQ(typedPath("/data/scenes", "a.json"), fs::path("/data/scenes/a.json"));
    EXPECT_EQ(typedPath("/data/scenes", "../meshes/m.glb"), fs::path("/data/meshes/m.glb"));
    EXPECT_EQ(typedPath("/data/scenes", "/tmp/x.json"), fs::path("/tmp/x.json"));
    EXPECT_EQ(typedPath("/data/scenes", "~/x.json", "/home/u"), fs::path("/home/u/x.json"));
    EXPECT_EQ(typedPath("/data/scenes", "~/x.json"), fs::path("/data/scenes/~/x.json"))
        << "without a home, ~ is a name";
    // A file field names a chosen file relative to the scene's folder when it is inside it.
    EXPECT_EQ(fileFieldText("/data/scenes/textures/a.png", "/data/scenes"), "textures/a.png");
    EXPECT_EQ(fileFieldText("/data/other/a.png", "/data/scenes"), "/data/other/a.png");
    EXPECT_EQ(fileFieldText("/data/other/a.png", ""), "/data/other/a.png") << "no scene file";
}

TEST_F(ViewerFiles, RecentFilesLiveInTheConfigFolder) {
    EXPECT_EQ(recentFilesPath("/cfg", "/home/u"), fs::path("/cfg/rmsc/recent.json"));
    EXPECT_EQ(recentFilesPath("relative", "/home/u"), fs::path("/home/u/.config/rmsc/recent.json"))
        << "XDG: a relative XDG_CONFIG_HOME is ignored";
    EXPECT_EQ(recentFilesPath(nullptr, "/home/u"), fs::path("/home/u/.config/rmsc/recent.json"));
    EXPECT_EQ(recentFilesPath(nullptr, nullptr), fs::path());
}

TEST_F(ViewerFiles, RecentFilesAreBoundedNewestFirstAndRoundTrip) {
    std::vector<fs::path> recent;
    for (std::size_t i = 0; i < kMaxRecentFiles + 3; ++i)
        addRecentFile(recent, folder / ("s" + std::to_string(i) + ".json"));
    ASSERT_EQ(recent.size(), kMaxRecentFiles);
    EXPECT_EQ(recent.front(), folder / ("s" + std::to_string(kMaxRecentFiles + 2) + ".json"));
    addRecentFile(recent, folder / "sub" / ".." / "s5.json");
    EXPECT_EQ(recent.front(), folder / "s5.json") << "made normal, moved first";
    EXPECT_EQ(std::count(recent.begin(), recent.end(), folder / "s5.json"), 1) << "once";
    EXPECT_EQ(recent.size(), kMaxRecentFiles);

    const fs::path file = folder / "config" / "rmsc" / "recent.json";
    std::string error;
    EXPECT_TRUE(loadRecentFiles(file, error).empty()) << "none yet";
    EXPECT_EQ(error, "");
    ASSERT_TRUE(saveRecentFiles(file, recent, error)) << error;
    EXPECT_EQ(loadRecentFiles(file, error), recent);
    EXPECT_EQ(error, "");
    EXPECT_FALSE(fs::exists(file.string() + ".bak")) << "no backup of a list";
    EXPECT_NE(read(file).find("\"files\""), std::string::npos);

    // Missing files stay until asked to go.
    write(folder / "s5.json", "{}");
    removeMissingFiles(recent);
    EXPECT_EQ(recent, std::vector<fs::path>{folder / "s5.json"});
}

TEST_F(ViewerFiles, ABrokenRecentFileSaysWhereAndStartsEmpty) {
    const fs::path file = folder / "recent.json";
    std::string error;
    write(file, "not json");
    EXPECT_TRUE(loadRecentFiles(file, error).empty());
    EXPECT_NE(error.find(file.string()), std::string::npos) << error;
    error.clear();
    write(file, R"({"files": ["/a.json", 3]})");
    EXPECT_TRUE(loadRecentFiles(file, error).empty());
    EXPECT_NE(error.find("/files/1: expected a file path"), std::string::npos) << error;
    error.clear();
    write(file, R"({"files": {}})");
    EXPECT_TRUE(loadRecentFiles(file, error).empty());
    EXPECT_NE(error.find("/files: expected an array"), std::string::npos) << error;
}

TEST_F(ViewerFiles, ARecentFileThatCannotBeWrittenSaysWhy) {
    write(folder / "blocker", "a file where the folder would be");
    std::string error;
    EXPECT_FALSE(saveRecentFiles(folder / "blocker" / "rmsc" / "recent.json", {"/a.json"}, error));
    EXPECT_NE(error.find("blocker"), std::string::npos) << error;
}

TEST_F(ViewerFiles, DroppedFiles) {
    EXPECT_EQ(droppedFileKind("/x/a.JSON"), DroppedKind::Scene);
    EXPECT_EQ(droppedFileKind("/x/duck.glb"), DroppedKind::Mesh);
    EXPECT_EQ(droppedFileKind("/x/duck.gltf"), DroppedKind::Mesh);
    EXPECT_EQ(droppedFileKind("/x/image.png"), DroppedKind::Unsupported);
    EXPECT_NE(droppedFileRefusal("/x/image.png").find("/x/image.png: cannot be dropped here"),
              std::string::npos);

    Scene scene;
    scene.file = folder / "scene.json";
    Selection selection;
    const int index =
        addMeshAt(scene, selection, folder / "models" / "duck.glb", glm::vec3(1.0f, 2.0f, 3.0f));
    ASSERT_EQ(index, 0);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].transform.position, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(scene.meshes[0].file, "models/duck.glb") << "relative to the scene's folder";
    EXPECT_EQ(scene.meshes[0].name, "duck");
    EXPECT_EQ(selection.kind, SelectionKind::Mesh);
    EXPECT_EQ(selection.index, 0);
}
