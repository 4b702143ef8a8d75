// Editing material textures in the editor (editor/material_texture_edits.hpp): a file that
// loads is set (resolved against the scene's folder, keeping scale and sharpness) and undoable;
// a missing file, a file that is not an image, and one texture too many are refused with a
// reason and leave the scene exactly as it was; an empty file removes the texture.
#include "editor/document.hpp"
#include "editor/material_texture_edits.hpp"
#include "scene/material_textures.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rmsc;
using namespace rmsc::editor;
namespace fs = std::filesystem;

namespace {

const fs::path kTextures = fs::path(RMSC_TEST_SOURCE_DIR) / "samples/assets/textures";

class MaterialTextureEdits : public ::testing::Test {
  protected:
    fs::path folder;
    Scene scene;
    void SetUp() override {
        folder = fs::temp_directory_path() /
                 ("rmsc-texture-edits-" +
                  std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder);
        fs::create_directories(folder / "textures");
        for (const char* name : {"bricks_color.png", "bricks_normal.png", "tiles_color.png"})
            fs::copy(kTextures / name, folder / "textures" / name);
        std::ofstream(folder / "textures" / "not_an_image.png") << "hello";
        scene = emptyScene();
        scene.file = folder / "scene.json";
        Material brick;
        brick.name = "brick";
        brick.baseColorTexture.scale = 2.0f;
        brick.baseColorTexture.sharpness = 8.0f;
        scene.materials.push_back(brick);
    }
    void TearDown() override { fs::remove_all(folder); }
};

} // namespace

TEST_F(MaterialTextureEdits, SetsAFileThatLoadsKeepingScaleAndSharpness) {
    std::string error;
    ASSERT_TRUE(setMaterialTextureFile(scene, 0, TextureSlot::BaseColor,
                                       "textures/bricks_color.png", diskFileSource(), error))
        << error;
    const MaterialTexture& texture = scene.materials[0].baseColorTexture;
    EXPECT_EQ(texture.file, "textures/bricks_color.png"); // as typed: relative to the scene
    EXPECT_EQ(texture.path, folder / "textures" / "bricks_color.png");
    EXPECT_FLOAT_EQ(texture.scale, 2.0f);
    EXPECT_FLOAT_EQ(texture.sharpness, 8.0f);
    EXPECT_FALSE(scene.materials[0].normalTexture.present());
    // It is written to the file like a texture read from one.
    EXPECT_NE(sceneToJson(scene).find("\"base_color_texture\""), std::string::npos);
}

TEST_F(MaterialTextureEdits, RefusesMissingAndBrokenFilesAndKeepsTheScene) {
    std::string error;
    ASSERT_TRUE(setMaterialTextureFile(scene, 0, TextureSlot::Normal, "textures/bricks_normal.png",
                                       diskFileSource(), error));
    const std::string before = sceneToJson(scene);
    EXPECT_FALSE(setMaterialTextureFile(scene, 0, TextureSlot::Normal, "textures/missing.png",
                                        diskFileSource(), error));
    EXPECT_NE(error.find("cannot read texture"), std::string::npos) << error;
    EXPECT_NE(error.find("missing.png"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_EQ(scene.materials[0].normalTexture.path, folder / "textures" / "bricks_normal.png");
    error.clear();
    EXPECT_FALSE(setMaterialTextureFile(scene, 0, TextureSlot::Normal, "textures/not_an_image.png",
                                        diskFileSource(), error));
    EXPECT_NE(error.find("not a usable image"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_FALSE(setMaterialTextureFile(scene, 5, TextureSlot::Normal, "textures/tiles_color.png",
                                        diskFileSource(), error));
}

TEST_F(MaterialTextureEdits, RefusesOneTextureTooMany) {
    // Fill every texture unit with distinct files, in materials after the one being edited.
    for (int i = 0; i < kMaxSdfMaterialTextures; ++i)
        fs::copy(kTextures / "tiles_color.png",
                 folder / "textures" / ("copy" + std::to_string(i) + ".png"));
    std::string error;
    for (int i = 0; i < kMaxSdfMaterialTextures; ++i) {
        Material m;
        m.name = "m" + std::to_string(i);
        scene.materials.push_back(m);
        ASSERT_TRUE(setMaterialTextureFile(
            scene, int(scene.materials.size()) - 1, TextureSlot::Roughness,
            "textures/copy" + std::to_string(i) + ".png", diskFileSource(), error))
            << error;
    }
    const std::string before = sceneToJson(scene);
    EXPECT_FALSE(setMaterialTextureFile(scene, 0, TextureSlot::BaseColor,
                                        "textures/bricks_color.png", diskFileSource(), error));
    EXPECT_NE(error.find("one too many"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    // A file already in use in the same colour space needs no new unit.
    EXPECT_TRUE(setMaterialTextureFile(scene, 0, TextureSlot::Normal, "textures/copy0.png",
                                       diskFileSource(), error))
        << error;
}

TEST_F(MaterialTextureEdits, EmptyFileRemovesTheTexture) {
    std::string error;
    ASSERT_TRUE(setMaterialTextureFile(scene, 0, TextureSlot::BaseColor,
                                       "textures/bricks_color.png", diskFileSource(), error));
    ASSERT_TRUE(
        setMaterialTextureFile(scene, 0, TextureSlot::BaseColor, "", diskFileSource(), error));
    EXPECT_FALSE(scene.materials[0].baseColorTexture.present());
    EXPECT_EQ(sceneToJson(scene).find("base_color_texture"), std::string::npos);
}

TEST_F(MaterialTextureEdits, ASceneWithoutAFileStoresTheAbsolutePath) {
    scene.file.clear();
    const fs::path previous = fs::current_path();
    fs::current_path(folder);
    std::string error;
    const bool set = setMaterialTextureFile(scene, 0, TextureSlot::BaseColor,
                                            "textures/tiles_color.png", diskFileSource(), error);
    fs::current_path(previous);
    ASSERT_TRUE(set) << error;
    EXPECT_TRUE(fs::path(scene.materials[0].baseColorTexture.file).is_absolute());
    EXPECT_TRUE(fs::equivalent(scene.materials[0].baseColorTexture.file,
                               folder / "textures" / "tiles_color.png"));
}

TEST_F(MaterialTextureEdits, AnAppliedFileIsOneUndoStep) {
    Document document(scene, scene.file);
    std::string error;
    Scene candidate = document.scene();
    ASSERT_TRUE(setMaterialTextureFile(candidate, 0, TextureSlot::BaseColor,
                                       "textures/bricks_color.png", diskFileSource(), error));
    document.apply("Texture file", [&](Scene& s, Selection&) { s = candidate; });
    EXPECT_TRUE(document.scene().materials[0].baseColorTexture.present());
    ASSERT_TRUE(document.undo());
    EXPECT_FALSE(document.scene().materials[0].baseColorTexture.present());
    ASSERT_TRUE(document.redo());
    EXPECT_EQ(document.scene().materials[0].baseColorTexture.file, "textures/bricks_color.png");
}
