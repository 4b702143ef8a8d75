// The editor's commands for the scene's settings outside the SDF tree: the sky's type and image
// file (editor/environment_edits.hpp), a mesh instance's glTF file (editor/mesh_file_edits.hpp)
// and the camera's position, target and up (editor/camera_edits.hpp). A value that loads is
// taken and saved as the reader reads it; a missing or broken file, an image sky without a file
// and a camera the reader refuses are refused with the reason and leave the scene as it was.
// The environment fields' ends (scene/environment_spec.hpp) are values a save accepts, and just
// past them the reader refuses: the fields and the reader use the same table.
#include "editor/camera_edits.hpp"
#include "editor/document.hpp"
#include "editor/environment_edits.hpp"
#include "editor/mesh_file_edits.hpp"
#include "editor/param_fields.hpp"
#include "editor/scene_check.hpp"
#include "scene/camera_spec.hpp"
#include "scene/environment_spec.hpp"
#include "scene/scene_json.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

using namespace rmsc;
using namespace rmsc::editor;
namespace fs = std::filesystem;

namespace {

const fs::path kSamples = fs::path(RMSC_TEST_SOURCE_DIR) / "samples/assets";

// A 2x1 Radiance image, flat (not run-length encoded: stb_image reads rows under 8 pixels so).
std::string tinyHdr() {
    std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
    for (int i = 0; i < 2; ++i)
        text += std::string{char(128), char(96), char(64), char(129)};
    return text;
}

class SceneSettingsEdits : public test::TempFolderTest {
  protected:
    Scene scene;
    void SetUp() override {
        TempFolderTest::SetUp();
        write(folder_ / "sky.hdr", tinyHdr());
        write(folder_ / "not_an_image.hdr", "hello");
        fs::copy(kSamples / "cube.glb", folder_ / "cube.glb");
        fs::copy(kSamples / "sphere.gltf", folder_ / "sphere.gltf");
        write(folder_ / "broken.gltf", "{\"asset\": ");
        scene = emptyScene();
        scene.file = folder_ / "scene.json";
    }
    // The scene's text loads (as every save checks it); `why` gets the errors.
    bool saves(const Scene& s, std::string& why) const {
        Diagnostics diagnostics;
        const bool ok = checkSceneText(sceneToJson(s), s.file, diagnostics);
        why = firstErrors(diagnostics);
        return ok;
    }
};

} // namespace

TEST_F(SceneSettingsEdits, SkyImageThatLoadsIsSetSavedAndUndoable) {
    scene.environment.rotationDegrees = 30.0f;
    Document document(scene, scene.file);
    Scene candidate = document.scene();
    std::string error;
    ASSERT_TRUE(setSkyImageFile(candidate, "sky.hdr", diskFileSource(), error)) << error;
    document.apply("Sky image", [&](Scene& s, Selection&) { s = candidate; });
    const Environment& e = document.scene().environment;
    EXPECT_EQ(e.sky, SkyType::Image);
    EXPECT_EQ(e.imageFile, "sky.hdr"); // as typed: relative to the scene
    EXPECT_EQ(e.imagePath, folder_ / "sky.hdr");
    EXPECT_FLOAT_EQ(e.rotationDegrees, 30.0f);
    std::string why;
    EXPECT_TRUE(saves(document.scene(), why)) << why;
    Diagnostics diagnostics;
    const auto read = parseScene(sceneToJson(document.scene()), scene.file, diagnostics);
    ASSERT_TRUE(read) << diagnostics.format();
    EXPECT_EQ(read->environment.sky, SkyType::Image);
    EXPECT_EQ(read->environment.imagePath, folder_ / "sky.hdr");
    ASSERT_TRUE(document.undo());
    EXPECT_EQ(document.scene().environment.sky, SkyType::None);
}

TEST_F(SceneSettingsEdits, SkyImagesThatDoNotLoadAreRefusedAndChangeNothing) {
    std::string error;
    ASSERT_TRUE(setSkyType(scene.environment, SkyType::Gradient, error)) << error;
    const std::string before = sceneToJson(scene);
    EXPECT_FALSE(setSkyImageFile(scene, "missing.hdr", diskFileSource(), error));
    EXPECT_NE(error.find("cannot read the sky image"), std::string::npos) << error;
    EXPECT_NE(error.find("missing.hdr"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_FALSE(setSkyImageFile(scene, "not_an_image.hdr", diskFileSource(), error));
    EXPECT_NE(error.find("is not a decodable image"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_FALSE(setSkyImageFile(scene, "", diskFileSource(), error));
    EXPECT_NE(error.find("got \"\""), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_EQ(scene.environment.sky, SkyType::Gradient);
    EXPECT_TRUE(scene.environment.imagePath.empty());
}

TEST_F(SceneSettingsEdits, AnImageSkyNeedsItsFileFirst) {
    std::string error;
    EXPECT_FALSE(setSkyType(scene.environment, SkyType::Image, error));
    EXPECT_NE(error.find("needs its file"), std::string::npos) << error;
    EXPECT_EQ(scene.environment.sky, SkyType::None); // a save would have failed: no "file"
    for (SkyType type : {SkyType::Constant, SkyType::Gradient, SkyType::None}) {
        ASSERT_TRUE(setSkyType(scene.environment, type, error)) << error;
        EXPECT_EQ(scene.environment.sky, type);
        std::string why;
        EXPECT_TRUE(saves(scene, why)) << why;
    }
    // Once it has a file, the sky can leave the image and come back to it.
    ASSERT_TRUE(setSkyImageFile(scene, "sky.hdr", diskFileSource(), error)) << error;
    ASSERT_TRUE(setSkyType(scene.environment, SkyType::Constant, error));
    ASSERT_TRUE(setSkyType(scene.environment, SkyType::Image, error)) << error;
    std::string why;
    EXPECT_TRUE(saves(scene, why)) << why;
}

// The fields clamp to the ends of the reader's ranges: each end saves, and a value just past it
// does not.
TEST_F(SceneSettingsEdits, EveryEnvironmentValueTheFieldsAcceptLoads) {
    std::string error;
    ASSERT_TRUE(setSkyImageFile(scene, "sky.hdr", diskFileSource(), error)) << error;
    struct Field {
        const char* name;
        float Environment::*member;
        ParamRange range;
    };
    const Field fields[] = {
        {"rotation", &Environment::rotationDegrees, kSkyRotationRange},
        {"intensity", &Environment::intensity, kEnvironmentIntensityRange},
        {"fog density", &Environment::fogDensity, kFogDensityRange},
    };
    int pastChecked = 0;
    for (const Field& field : fields) {
        const FloatFieldRange r = floatFieldRange(field.range);
        for (float end : {r.min, r.max}) {
            Scene s = scene;
            s.environment.*field.member = end;
            if (field.member != &Environment::fogDensity) s.environment.fogDensity = 0.1f;
            std::string why;
            EXPECT_TRUE(saves(s, why)) << field.name << " = " << end << ": " << why;
        }
        for (float past : {r.min - 1.0f, r.max * 1.01f}) {
            if (!std::isfinite(past) || past == r.max) continue; // unbounded above
            // A fog density <= 0 is "no fog": the writer leaves the fog out.
            if (field.member == &Environment::fogDensity && past < r.min) continue;
            Scene s = scene;
            s.environment.*field.member = past;
            s.environment.fogDensity = field.member == &Environment::fogDensity ? past : 0.1f;
            std::string why;
            EXPECT_FALSE(saves(s, why)) << field.name << " = " << past;
            ++pastChecked;
        }
    }
    EXPECT_EQ(pastChecked, 4); // rotation below and above, intensity below, density above
}

TEST_F(SceneSettingsEdits, MeshFileThatLoadsIsSetKeepingTheInstance) {
    MeshInstance mesh;
    mesh.name = "crate";
    mesh.file = "cube.glb";
    mesh.path = folder_ / "cube.glb";
    mesh.transform.position = {1.0f, 2.0f, 3.0f};
    scene.meshes.push_back(mesh);
    std::string error;
    ASSERT_TRUE(setMeshFile(scene, 0, "sphere.gltf", diskFileSource(), error)) << error;
    const MeshInstance& changed = scene.meshes[0];
    EXPECT_EQ(changed.file, "sphere.gltf");
    EXPECT_EQ(changed.path, folder_ / "sphere.gltf");
    EXPECT_EQ(changed.name, "crate");
    EXPECT_EQ(changed.transform.position, glm::vec3(1.0f, 2.0f, 3.0f));
    Diagnostics diagnostics;
    const auto read = parseScene(sceneToJson(scene), scene.file, diagnostics);
    ASSERT_TRUE(read) << diagnostics.format();
    EXPECT_EQ(read->meshes[0].path, folder_ / "sphere.gltf");
}

TEST_F(SceneSettingsEdits, MeshFilesThatDoNotLoadAreRefusedAndChangeNothing) {
    std::string error;
    scene.meshes.push_back({});
    ASSERT_TRUE(setMeshFile(scene, 0, "cube.glb", diskFileSource(), error)) << error;
    const std::string before = sceneToJson(scene);
    EXPECT_FALSE(setMeshFile(scene, 0, "missing.gltf", diskFileSource(), error));
    EXPECT_NE(error.find("\"missing.gltf\" does not load"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_FALSE(setMeshFile(scene, 0, "broken.gltf", diskFileSource(), error));
    EXPECT_NE(error.find("\"broken.gltf\" does not load"), std::string::npos) << error;
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_FALSE(setMeshFile(scene, 0, "", diskFileSource(), error));
    EXPECT_NE(error.find("got \"\""), std::string::npos) << error;
    EXPECT_FALSE(setMeshFile(scene, 3, "sphere.gltf", diskFileSource(), error));
    EXPECT_EQ(error, "no such mesh");
    EXPECT_EQ(sceneToJson(scene), before);
    EXPECT_EQ(scene.meshes[0].path, folder_ / "cube.glb");
}

TEST_F(SceneSettingsEdits, CameraFramesTheReaderRefusesAreRefused) {
    Camera& camera = scene.camera;
    camera.position = {0.0f, 1.0f, 5.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    Camera wanted = camera;
    wanted.position = {3.0f, 2.0f, 1.0f};
    wanted.up = {0.0f, 0.0f, 1.0f};
    wanted.fovYDegrees = 90.0f; // the lens is not the frame's
    std::string error;
    ASSERT_TRUE(setCameraFrame(camera, wanted, error)) << error;
    EXPECT_EQ(camera.position, wanted.position);
    EXPECT_EQ(camera.up, wanted.up);
    EXPECT_FLOAT_EQ(camera.fovYDegrees, 45.0f);
    std::string why;
    EXPECT_TRUE(saves(scene, why)) << why;

    const Camera before = camera;
    Camera onTarget = camera;
    onTarget.target = onTarget.position;
    Camera alongView = camera;
    alongView.up = camera.target - camera.position;
    Camera zeroUp = camera;
    zeroUp.up = glm::vec3(0.0f);
    for (const auto& [refused, key] :
         {std::pair{onTarget, "target"}, std::pair{alongView, "up"}, std::pair{zeroUp, "up"}}) {
        EXPECT_FALSE(setCameraFrame(camera, refused, error)) << key;
        EXPECT_EQ(error.rfind(std::string(key) + ": ", 0), 0u) << error;
        EXPECT_EQ(camera.position, before.position);
        EXPECT_EQ(camera.target, before.target);
        EXPECT_EQ(camera.up, before.up);
        // The reader refuses it too, at that key, with the same words.
        Scene s = scene;
        s.camera = refused;
        Diagnostics diagnostics;
        EXPECT_FALSE(checkSceneText(sceneToJson(s), s.file, diagnostics));
        EXPECT_NE(
            firstErrors(diagnostics)
                .find("/camera/" + std::string(key) + ": " + error.substr(error.find(": ") + 2)),
            std::string::npos)
            << firstErrors(diagnostics) << " / " << error;
    }
}
