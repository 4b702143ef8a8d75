// The viewer's camera model beyond flying (editor/fly_camera.hpp, editor/camera_edits.hpp,
// editor/view_bookmarks.hpp): the views along the axes, the orthographic projection and its
// zoom, the level horizon with roll as an option, whether the view differs from the scene
// camera (asked on save), bookmarks; and the scene file's orthographic camera, read, written
// and refused with its JSON pointer.
#include "editor/camera_edits.hpp"
#include "editor/fly_camera.hpp"
#include "editor/view_bookmarks.hpp"
#include "scene/scene_json.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "y " << actual.y << " z " << actual.z;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "x " << actual.x << " z " << actual.z;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "x " << actual.x << " y " << actual.y;
}

// A camera 4 in front of (1, 0, 0), looking at it.
FlyCamera lookingAtPivot() {
    Camera camera;
    camera.position = glm::vec3(1, 0, 4);
    camera.target = glm::vec3(1, 0, 0);
    FlyCamera fly;
    fly.setFromCamera(camera);
    return fly;
}

} // namespace

TEST(CameraViews, AxisViewsLookAtTheSamePointFromTheSameDistance) {
    struct Expected {
        AxisView view;
        glm::vec3 forward, up;
    };
    const Expected views[] = {
        {AxisView::Front, {0, 0, -1}, {0, 1, 0}}, {AxisView::Back, {0, 0, 1}, {0, 1, 0}},
        {AxisView::Right, {-1, 0, 0}, {0, 1, 0}}, {AxisView::Left, {1, 0, 0}, {0, 1, 0}},
        {AxisView::Top, {0, -1, 0}, {0, 0, -1}},  {AxisView::Bottom, {0, 1, 0}, {0, 0, 1}},
    };
    for (const Expected& e : views) {
        FlyCamera fly = lookingAtPivot();
        fly.viewFrom(e.view);
        expectNear(fly.forward(), e.forward);
        expectNear(fly.up(), e.up);
        expectNear(fly.position + fly.forward() * fly.focusDistance, {1, 0, 0}, 1e-4f);
        EXPECT_NEAR(fly.focusDistance, 4.0f, 1e-5f);
        EXPECT_EQ(fly.axisView(), e.view) << axisViewName(e.view);
    }
    // A view turned off the axis is none of them.
    FlyCamera turned = lookingAtPivot();
    turned.orbit(glm::vec3(1, 0, 0), glm::vec2(10, 0));
    EXPECT_FALSE(turned.axisView().has_value());
    // The right view shows -Z to the right, as Blender's shows its +Y.
    FlyCamera right = lookingAtPivot();
    right.viewFrom(AxisView::Right);
    expectNear(right.right(), {0, 0, -1});
}

TEST(CameraViews, OrthographicKeepsWhatTheFocusPlaneShowsAndZooms) {
    FlyCamera fly = lookingAtPivot();
    // 90 degrees at 4 away: 8 high.
    fly.setOrthographic(true, 90.0f);
    EXPECT_TRUE(fly.orthographic);
    EXPECT_NEAR(fly.orthoHeight, 8.0f, 1e-4f);
    expectNear(fly.position, {1, 0, 4});
    const Camera scene;
    const Camera out = fly.toCamera(scene);
    EXPECT_EQ(out.projection, CameraProjection::Orthographic);
    EXPECT_EQ(out.orthoHeight, fly.orthoHeight);
    // Zoomed in one notch (1.25 times less), then back to perspective: the camera moves to
    // where 6.4 high fills the view, 3.2 from the point.
    fly.zoom(1.0f);
    EXPECT_NEAR(fly.orthoHeight, 6.4f, 1e-4f);
    fly.setOrthographic(false, 90.0f);
    EXPECT_FALSE(fly.orthographic);
    EXPECT_NEAR(fly.focusDistance, 3.2f, 1e-4f);
    expectNear(fly.position, {1, 0, 3.2f}, 1e-4f);
    // Framing a sphere of radius 1 orthographically shows 2.2 of height.
    fly.setOrthographic(true, 90.0f);
    fly.frame(glm::vec3(0), 1.0f, 90.0f);
    EXPECT_NEAR(fly.orthoHeight, 2.2f, 1e-5f);
    // The scene camera's projection comes in with it.
    Camera ortho;
    ortho.projection = CameraProjection::Orthographic;
    ortho.orthoHeight = 3.0f;
    FlyCamera again;
    again.setFromCamera(ortho);
    EXPECT_TRUE(again.orthographic);
    EXPECT_EQ(again.orthoHeight, 3.0f);
}

TEST(CameraViews, TheHorizonStaysLevelUnlessRollIsAllowed) {
    FlyCamera fly = lookingAtPivot();
    FlyInput roll;
    roll.roll = 1.0f;
    EXPECT_FALSE(fly.update(roll, 0.5f)); // Q / E do nothing
    expectNear(fly.up(), {0, 1, 0});
    fly.allowRoll = true;
    EXPECT_TRUE(fly.update(roll, 0.5f));
    EXPECT_GT(std::abs(fly.right().y), 0.1f); // rolled
    // Levelled again: looking the same way, its right axis horizontal, up above.
    const glm::vec3 forward = fly.forward();
    fly.level();
    expectNear(fly.forward(), forward);
    EXPECT_NEAR(fly.right().y, 0.0f, 1e-5f);
    EXPECT_GT(fly.up().y, 0.0f);
    // Without roll, looking up past the zenith stops there instead of turning over.
    fly.allowRoll = false;
    FlyInput look;
    look.look = glm::vec2(0, -500); // 2 radians up
    fly.update(look, 0.1f);
    EXPECT_GE(fly.up().y, 0.0f);
    EXPECT_NEAR(fly.right().y, 0.0f, 1e-5f);
    // Orbiting over the top stops as well.
    FlyCamera orbiting = lookingAtPivot();
    orbiting.orbit(glm::vec3(1, 0, 0), glm::vec2(0, 600));
    EXPECT_GE(orbiting.up().y, 0.0f);
    orbiting.allowRoll = true;
    orbiting.orbit(glm::vec3(1, 0, 0), glm::vec2(0, 600));
    EXPECT_LT(orbiting.up().y, 0.0f); // allowed: over the top and upside down
}

TEST(CameraViews, TheViewDiffersFromTheSceneCameraWhenItShowsSomethingElse) {
    Camera scene;
    scene.position = glm::vec3(0, 0.3f, 4);
    scene.target = glm::vec3(0);
    scene.up = glm::vec3(0, 1, 0);
    FlyCamera fly;
    fly.setFromCamera(scene);
    // Through the fly camera and back (target at another distance, up made orthogonal): the
    // same view.
    EXPECT_FALSE(viewDiffersFromCamera(fly.toCamera(scene), scene));
    Camera lens = fly.toCamera(scene);
    lens.fovYDegrees = 80.0f; // the lens is the scene camera's own
    EXPECT_FALSE(viewDiffersFromCamera(lens, scene));
    FlyCamera moved = fly;
    moved.position.x += 1e-3f;
    EXPECT_TRUE(viewDiffersFromCamera(moved.toCamera(scene), scene));
    FlyCamera turned = fly;
    turned.orbit(glm::vec3(0), glm::vec2(3, 0)); // 0.012 radians
    EXPECT_TRUE(viewDiffersFromCamera(turned.toCamera(scene), scene));
    FlyCamera rolled = fly;
    rolled.allowRoll = true;
    FlyInput roll;
    roll.roll = 1.0f;
    rolled.update(roll, 0.01f);
    EXPECT_TRUE(viewDiffersFromCamera(rolled.toCamera(scene), scene));
    FlyCamera ortho = fly;
    ortho.setOrthographic(true, scene.fovYDegrees);
    EXPECT_TRUE(viewDiffersFromCamera(ortho.toCamera(scene), scene));
    Camera orthoScene = ortho.toCamera(scene);
    EXPECT_FALSE(viewDiffersFromCamera(ortho.toCamera(scene), orthoScene));
    ortho.zoom(0.1f);
    EXPECT_TRUE(viewDiffersFromCamera(ortho.toCamera(scene), orthoScene));
}

TEST(CameraViews, BookmarksKeepNineViews) {
    ViewBookmarks bookmarks;
    Camera view;
    view.position = glm::vec3(1, 2, 3);
    view.projection = CameraProjection::Orthographic;
    EXPECT_FALSE(bookmarks.recall(1).has_value());
    EXPECT_TRUE(bookmarks.store(1, view));
    EXPECT_TRUE(bookmarks.store(9, Camera{}));
    EXPECT_FALSE(bookmarks.store(0, view));
    EXPECT_FALSE(bookmarks.store(10, view));
    ASSERT_TRUE(bookmarks.recall(1).has_value());
    EXPECT_EQ(bookmarks.recall(1)->position, view.position);
    EXPECT_EQ(bookmarks.recall(1)->projection, CameraProjection::Orthographic);
    EXPECT_TRUE(bookmarks.recall(9).has_value());
    EXPECT_FALSE(bookmarks.recall(5).has_value());
    EXPECT_FALSE(bookmarks.recall(10).has_value());
    // Recalled into the fly camera, the view is the one stored.
    FlyCamera fly;
    fly.setFromCamera(*bookmarks.recall(1));
    EXPECT_FALSE(viewDiffersFromCamera(fly.toCamera(Camera{}), view));
}

TEST(CameraViews, SceneFilesHoldAnOrthographicCamera) {
    const std::string text =
        R"({"version": 1, "camera": {"position": [0, 0, 5], "target": [0, 0, 0],
        "projection": "orthographic", "ortho_height": 3.5}})";
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(text, "ortho.json", d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    EXPECT_EQ(scene->camera.projection, CameraProjection::Orthographic);
    EXPECT_EQ(scene->camera.orthoHeight, 3.5f);
    // Written back and read again: the same.
    const std::string written = sceneToJson(*scene);
    EXPECT_NE(written.find("\"projection\": \"orthographic\""), std::string::npos) << written;
    const std::optional<Scene> again = parseScene(written, "ortho.json", d);
    ASSERT_TRUE(again) << d.format();
    EXPECT_EQ(again->camera.projection, CameraProjection::Orthographic);
    EXPECT_EQ(again->camera.orthoHeight, 3.5f);
    // A perspective camera writes neither key.
    const std::string perspective = sceneToJson(Scene{});
    EXPECT_EQ(perspective.find("projection"), std::string::npos) << perspective;
    EXPECT_EQ(perspective.find("ortho_height"), std::string::npos) << perspective;
}

TEST(CameraViews, BadProjectionsAreRefusedAtTheirPointer) {
    auto problems = [](const std::string& camera) {
        Diagnostics d;
        parseScene(R"({"version": 1, "camera": )" + camera + "}", "bad.json", d);
        return d;
    };
    Diagnostics d = problems(R"({"projection": "fisheye"})");
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/camera/projection");
    EXPECT_NE(d.items[0].message.find("unknown projection \"fisheye\"; expected \"perspective\" or "
                                      "\"orthographic\""),
              std::string::npos)
        << d.format();
    d = problems(R"({"projection": "orthographic", "ortho_height": 0})");
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/camera/ortho_height");
    d = problems(R"({"projection": 3})");
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/camera/projection");
    // A height without the projection does nothing: a warning, not an error.
    d = problems(R"({"ortho_height": 2})");
    EXPECT_EQ(d.errorCount(), 0) << d.format();
    ASSERT_EQ(d.items.size(), 1u) << d.format();
    EXPECT_EQ(d.items[0].location, "/camera/ortho_height");
    EXPECT_EQ(d.items[0].severity, Severity::Warning);
}
