// The editor model's commands for lights and profile solids: adding a light of each type where
// asked (valid to save, undoable, refused at the light limit, and so is a copy), moving and turning
// lights with the gestures (each type only in the ways it has: no place for a directional light, no
// direction for a point light), clicking a light's marker, the lights' labels; adding an
// extrusion and a revolution (valid, named after the solid, framed by their size) and changing
// a profile's type (shared keys kept, the result still valid), each as one undo step.
#include "core/limits.hpp"
#include "editor/document.hpp"
#include "editor/gesture_target.hpp"
#include "editor/light_edits.hpp"
#include "editor/profile_edits.hpp"
#include "editor/scene_edits.hpp"
#include "scene/light_spec.hpp"
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/profiles.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

// The scene as saved, read back: nullopt (and a failure naming the problems) when the reader
// refuses it.
std::optional<Scene> saveAndReload(const Scene& scene) {
    Diagnostics diagnostics;
    std::optional<Scene> loaded = parseScene(sceneToJson(scene), "saved.json", diagnostics);
    EXPECT_TRUE(loaded) << diagnostics.format();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.format();
    return loaded;
}

// A camera at (0, 2, 5) looking along -z at (0, 2, 0), 640 x 360 pixels.
GestureView frontView() {
    GestureView view;
    const glm::mat4 projection =
        glm::perspective(glm::radians(45.0f), 640.0f / 360.0f, 0.05f, 100.0f);
    const glm::mat4 look = glm::lookAt(glm::vec3(0, 2, 5), glm::vec3(0, 2, 0), glm::vec3(0, 1, 0));
    view.viewProjection = projection * look;
    view.viewportSize = glm::vec2(640, 360);
    view.forward = glm::vec3(0, 0, -1);
    return view;
}

Scene sceneWithLights() {
    Scene scene = emptyScene();
    scene.lights.clear();
    addLight(scene, LightType::Directional, glm::vec3(-1, 2, 0));
    addLight(scene, LightType::Point, glm::vec3(0, 2, 0));
    addLight(scene, LightType::Spot, glm::vec3(1, 2, 0));
    return scene;
}

// Runs gesture `kind` (constrained to `axis`, -1 free) on the selection from the screen centre
// to `mouse`, as the viewer does: start, apply, commit. False when the selection does not take
// that gesture.
bool runGesture(Document& doc, GestureKind kind, int axis, glm::vec2 from, glm::vec2 mouse) {
    const std::optional<GestureTarget> target = gestureTarget(doc.scene(), doc.selection, kind);
    if (!target) return false;
    TransformGesture g;
    g.kind = kind;
    g.axis = axis;
    g.start = target->start;
    g.parentWorld = target->parentWorld;
    g.view = frontView();
    g.startMouse = from;
    setGestureTransform(doc.editScene(), doc.selection, gestureTransform(g, mouse));
    doc.markChanged("gesture");
    doc.commit();
    return true;
}

} // namespace

TEST(EditorLights, AddsEachTypeWhereAskedValidAndUndoable) {
    for (const LightType type : kLightTypes) {
        SCOPED_TRACE(std::string(lightTypeName(type)));
        Document doc(emptyScene());
        const std::size_t before = doc.scene().lights.size();
        const glm::vec3 at(0.5f, 1.5f, -2.0f);
        doc.apply("Add light", [&](Scene& s, Selection& selection) {
            selection = Selection::light(addLight(s, type, at));
        });
        ASSERT_EQ(doc.scene().lights.size(), before + 1);
        const Light& light = doc.scene().lights.back();
        EXPECT_EQ(light.type, type);
        EXPECT_EQ(light.position, at);
        EXPECT_EQ(doc.selection, Selection::light(int(before)));
        EXPECT_NE(light.name.find(lightTypeName(type)), std::string::npos) << light.name;
        if (type == LightType::Spot) {
            EXPECT_EQ(light.direction, glm::vec3(0, -1, 0));
        }
        // What is saved reads back as the same light.
        const std::optional<Scene> loaded = saveAndReload(doc.scene());
        ASSERT_TRUE(loaded);
        ASSERT_EQ(loaded->lights.size(), before + 1);
        EXPECT_EQ(loaded->lights.back().type, type);
        if (hasPosition(type)) {
            EXPECT_EQ(loaded->lights.back().position, at);
        }
        doc.undo();
        EXPECT_EQ(doc.scene().lights.size(), before);
    }
}

TEST(EditorLights, NoLightIsAddedPastTheLimit) {
    Scene scene = emptyScene();
    while (int(scene.lights.size()) < limits::kLights)
        ASSERT_GE(addLight(scene, LightType::Point, glm::vec3(0.0f)), 0);
    EXPECT_EQ(addLight(scene, LightType::Spot, glm::vec3(0.0f)), -1);
    EXPECT_EQ(int(scene.lights.size()), limits::kLights);
    // Nor copied past it: the scene and the selection stay as they were.
    EXPECT_EQ(duplicateLight(scene, 3), -1);
    const Selection selected = Selection::light(3);
    const Selection after = duplicateSelected(scene, selected);
    EXPECT_EQ(int(scene.lights.size()), limits::kLights);
    EXPECT_EQ(after.kind, SelectionKind::Light);
    EXPECT_EQ(after.index, 3);
    // One under the limit, the copy goes right after the original.
    scene.lights.pop_back();
    EXPECT_EQ(duplicateSelected(scene, selected).index, 4);
    EXPECT_EQ(int(scene.lights.size()), limits::kLights);
    EXPECT_EQ(scene.lights[4].name, scene.lights[3].name + " copy");
}

TEST(EditorLights, EachTypeTakesTheGesturesOfItsKeys) {
    const Scene scene = sceneWithLights();
    auto takes = [&](int light, GestureKind kind) {
        return gestureTarget(scene, Selection::light(light), kind).has_value();
    };
    EXPECT_FALSE(takes(0, GestureKind::Move)); // directional: no position in the file
    EXPECT_TRUE(takes(0, GestureKind::Rotate));
    EXPECT_TRUE(takes(1, GestureKind::Move));
    EXPECT_FALSE(takes(1, GestureKind::Rotate)); // point: no direction
    EXPECT_TRUE(takes(2, GestureKind::Move));
    EXPECT_TRUE(takes(2, GestureKind::Rotate));
    for (int i = 0; i < 3; ++i)
        EXPECT_FALSE(takes(i, GestureKind::Scale));
    EXPECT_FALSE(takes(3, GestureKind::Move)); // no such light
}

TEST(EditorLights, MovingAPointOrSpotLightAlongXIsOneUndoStep) {
    for (const int index : {1, 2}) {
        SCOPED_TRACE(index);
        Document doc(sceneWithLights());
        doc.selection = Selection::light(index);
        const glm::vec3 start = doc.scene().lights[std::size_t(index)].position;
        const glm::vec3 direction = doc.scene().lights[std::size_t(index)].direction;
        const glm::vec2 centre(320, 180);
        ASSERT_TRUE(runGesture(doc, GestureKind::Move, 0, centre, centre + glm::vec2(60, 25)));
        const Light& moved = doc.scene().lights[std::size_t(index)];
        // 60 pixels at 5 units with a 45 degree fov over 360 pixels: about 0.69 units.
        EXPECT_NEAR(moved.position.x - start.x,
                    60.0f * 2.0f * 5.0f * std::tan(glm::radians(22.5f)) / 360.0f, 1e-3f);
        EXPECT_FLOAT_EQ(moved.position.y, start.y);
        EXPECT_FLOAT_EQ(moved.position.z, start.z);
        EXPECT_NEAR(glm::length(moved.direction - direction), 0.0f, 1e-5f); // not turned
        EXPECT_EQ(doc.undoLabel(), "gesture");
        doc.undo();
        EXPECT_EQ(doc.scene().lights[std::size_t(index)].position, start);
    }
}

TEST(EditorLights, RotatingTurnsTheDirectionOfSpotAndDirectionalLights) {
    for (const int index : {0, 2}) {
        SCOPED_TRACE(index);
        Scene scene = sceneWithLights();
        scene.lights[std::size_t(index)].direction = glm::vec3(0, -1, 0);
        Document doc(scene);
        doc.selection = Selection::light(index);
        const glm::vec3 position = doc.scene().lights[std::size_t(index)].position;
        const glm::vec2 pivot = worldToScreen(frontView(), position);
        // A quarter turn counter-clockwise on screen about the view axis (+z towards the
        // viewer): straight down becomes pointing to +x.
        ASSERT_TRUE(runGesture(doc, GestureKind::Rotate, -1, pivot + glm::vec2(0, 50),
                               pivot + glm::vec2(50, 0)));
        const Light& turned = doc.scene().lights[std::size_t(index)];
        EXPECT_NEAR(turned.direction.x, 1.0f, 1e-4f);
        EXPECT_NEAR(turned.direction.y, 0.0f, 1e-4f);
        EXPECT_NEAR(turned.direction.z, 0.0f, 1e-4f);
        EXPECT_EQ(turned.position, position);
        ASSERT_TRUE(saveAndReload(doc.scene()));
        doc.undo();
        EXPECT_EQ(doc.scene().lights[std::size_t(index)].direction, glm::vec3(0, -1, 0));
    }
}

TEST(EditorLights, TheGestureTransformKeepsEveryDirection) {
    for (const glm::vec3 d : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0),
                              glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f))}) {
        Light light;
        light.type = LightType::Spot;
        light.direction = d;
        light.position = glm::vec3(1, 2, 3);
        Light copy = light;
        copy.direction = glm::vec3(0, 0, 1); // set again from the transform
        copy.position = glm::vec3(0.0f);
        setLightTransform(copy, lightTransform(light));
        EXPECT_NEAR(glm::length(copy.direction - d), 0.0f, 1e-5f);
        EXPECT_EQ(copy.position, light.position);
    }
}

TEST(EditorLights, AClickNearAMarkerPicksThatLight) {
    const Scene scene = sceneWithLights();
    const GestureView view = frontView();
    for (int i = 0; i < 3; ++i) {
        const glm::vec2 at = worldToScreen(view, scene.lights[std::size_t(i)].position);
        EXPECT_EQ(pickLight(scene, view, at + glm::vec2(3, -2), 10.0f), i);
    }
    EXPECT_EQ(pickLight(scene, view, glm::vec2(320, 40), 10.0f), -1); // far from every marker
    // A light behind the camera is never picked, even where it would project.
    Scene behind = scene;
    behind.lights[1].position = glm::vec3(0, 2, 10);
    EXPECT_EQ(pickLight(behind, view, glm::vec2(320, 180), 10.0f), -1);
}

TEST(EditorLights, LabelsSayTheType) {
    Light light;
    light.type = LightType::Spot;
    EXPECT_EQ(lightLabel(light, 1), "spot light 2");
    light.type = LightType::Point;
    EXPECT_EQ(lightLabel(light, 0), "point light 1");
    light.name = "key";
    EXPECT_EQ(lightLabel(light, 0), "key");
}

TEST(EditorProfiles, NewSolidsAreValidNamedAndSized) {
    for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
        SCOPED_TRACE(std::string(solid.name));
        Document doc(emptyScene());
        doc.apply("Add", [&](Scene& s, Selection& selection) {
            selection = Selection::sdf(insertSdfNode(s, selection, makeProfileShape(solid.solid)));
        });
        const SdfNode* node = findSdfNode(doc.scene(), doc.selection.sdfPath);
        ASSERT_TRUE(node && node->profile);
        EXPECT_EQ(node->profile->solid, solid.solid);
        EXPECT_EQ(displayName(*node), solid.name);
        SdfNode unnamed = *node;
        unnamed.name.clear();
        EXPECT_EQ(displayName(unnamed), solid.name); // not the ignored primitive's "sphere"
        const std::optional<Scene> loaded = saveAndReload(doc.scene());
        ASSERT_TRUE(loaded && loaded->sdf);
        const SdfNode* read = findSdfNode(*loaded, doc.selection.sdfPath);
        ASSERT_TRUE(read && read->profile);
        EXPECT_EQ(read->profile->solid, solid.solid);
        EXPECT_EQ(read->profile->type, node->profile->type);
        Diagnostics diagnostics;
        EXPECT_TRUE(compileSdf(*loaded->sdf, 0, "saved.json", diagnostics)) << diagnostics.format();
        // Framing sees the solid's own size.
        const std::optional<Bounds> bounds = selectionBounds(doc.scene(), doc.selection);
        ASSERT_TRUE(bounds);
        EXPECT_NEAR(bounds->radius, profileSolidRadius(*node->profile), 1e-6f);
        EXPECT_GE(bounds->radius, 0.5f);
        doc.undo();
        EXPECT_FALSE(doc.scene().sdf);
    }
    // A new revolution is a ring: its circle of radius 0.5 turns 1 out, so it reaches 1.5 out
    // (the bound holds the profile's box: at most sqrt(1.5^2 + 0.5^2)).
    const SdfNode ring = makeProfileShape(SdfProfileSolid::Revolution);
    EXPECT_FLOAT_EQ(ring.profile->offset, 1.0f);
    EXPECT_GE(profileSolidRadius(*ring.profile), 1.5f);
    EXPECT_LE(profileSolidRadius(*ring.profile), std::sqrt(1.5f * 1.5f + 0.5f * 0.5f) + 1e-6f);
}

TEST(EditorProfiles, ChangingTheTypeKeepsSharedKeysAndStaysValid) {
    Document doc(emptyScene());
    doc.apply("Add", [&](Scene& s, Selection& selection) {
        selection = Selection::sdf(
            insertSdfNode(s, selection, makeProfileShape(SdfProfileSolid::Extrusion)));
    });
    const std::vector<int> path = doc.selection.sdfPath;
    auto profile = [&]() -> const SdfProfile& { return *findSdfNode(doc.scene(), path)->profile; };
    auto change = [&](SdfProfileType type) {
        doc.apply("Edit profile", [&](Scene& s, Selection&) {
            changeProfileType(*findSdfNode(s, path)->profile, type);
        });
        EXPECT_EQ(profile().type, type);
        const std::optional<Scene> loaded = saveAndReload(doc.scene());
        ASSERT_TRUE(loaded);
        EXPECT_EQ(findSdfNode(*loaded, path)->profile->type, type);
    };
    doc.apply("Radius",
              [&](Scene& s, Selection&) { findSdfNode(s, path)->profile->radius = 2.0f; });
    change(SdfProfileType::RoundedRectangle);
    EXPECT_EQ(profile().halfSize, glm::vec2(0.5f, 0.5f)); // the catalogue's default
    EXPECT_FLOAT_EQ(profile().radius, 0.5f); // the circle's 2 kept, but within the half size
    doc.apply("Half size", [&](Scene& s, Selection&) {
        findSdfNode(s, path)->profile->halfSize = glm::vec2(0.8f, 0.3f);
    });
    change(SdfProfileType::Rectangle);
    EXPECT_EQ(profile().halfSize, glm::vec2(0.8f, 0.3f)); // kept
    change(SdfProfileType::RoundedRectangle);
    EXPECT_EQ(profile().halfSize, glm::vec2(0.8f, 0.3f)); // kept
    EXPECT_FLOAT_EQ(profile().radius, 0.1f); // a rectangle has none: the catalogue's default
    change(SdfProfileType::Polygon);
    const std::vector<glm::vec2> corners = {
        {-0.8f, -0.3f}, {0.8f, -0.3f}, {0.8f, 0.3f}, {-0.8f, 0.3f}};
    EXPECT_EQ(profile().points, corners);
    change(SdfProfileType::Circle);
    EXPECT_FLOAT_EQ(profile().radius, 0.5f); // a polygon has none: the catalogue's default
    // Every change was its own undo step: back to the rounded rectangle.
    doc.undo();
    EXPECT_EQ(profile().type, SdfProfileType::Polygon);
    doc.undo();
    EXPECT_EQ(profile().type, SdfProfileType::RoundedRectangle);
}
