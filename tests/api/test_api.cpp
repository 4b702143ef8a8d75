// The public C++ API (rmsc/rmsc.hpp) as a program embedding rmsc uses it: loading and its
// errors, edits by JSON pointer without shader compiles, rendering every output, drawing into a
// host's colour and depth textures in each supported depth convention (and refusing the
// others), the GL state a call must leave as it found it, and misuse of contexts and textures.
// The host side (textures, clears, glClipControl) is plain GL through the loader rmsc built.
#include <rmsc/rmsc.hpp>

#include <glad/gl.h> // before osmesa.h, which would include GL/gl.h

#include <EGL/egl.h>
#include <GL/osmesa.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <set>
#include <vector>

using namespace rmsc::api;

namespace {

// A unit sphere seen from 3 m: its front is at view depth 2 on the axis.
constexpr const char* kSphereScene = R"({
  "version": 1,
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov": 45, "near": 0.1, "far": 100},
  "materials": {"clay": {"base_color": "#e07a5f", "roughness": 0.5}},
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.6], "intensity": 3}],
  "sdf": {"shape": "sphere", "radius": 1, "material": "clay"}
})";
constexpr int kWidth = 64, kHeight = 48;

HeadlessContext& context() {
    static HeadlessContext shared(
        parseBackend(std::getenv("RMSC_TEST_BACKEND") ? std::getenv("RMSC_TEST_BACKEND") : "auto"));
    return shared;
}

Renderer& renderer() {
    context();
    static Renderer shared;
    return shared;
}

template <class T> T pixel(const Image& image, int x, int y, int channel = 0) {
    return image.data<T>()[(std::size_t(y) * image.width + x) * image.channels + channel];
}

// The test's host: an RGBA8 colour texture and a depth texture, cleared.
struct HostTextures {
    GLuint color = 0, depth = 0, framebuffer = 0;
    HostTextures(GLenum depthFormat, float clearDepth) {
        renderer(); // the context, and the GL functions loaded
        glCreateTextures(GL_TEXTURE_2D, 1, &color);
        glTextureStorage2D(color, 1, GL_RGBA8, kWidth, kHeight);
        glCreateTextures(GL_TEXTURE_2D, 1, &depth);
        glTextureStorage2D(depth, 1, depthFormat, kWidth, kHeight);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, color, 0);
        glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);
        const float blue[4] = {0, 0, 1, 1};
        glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, blue);
        glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &clearDepth);
    }
    ~HostTextures() {
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteTextures(1, &color);
        glDeleteTextures(1, &depth);
    }
    std::vector<std::uint8_t> readColor() const {
        std::vector<std::uint8_t> rgba(std::size_t(kWidth) * kHeight * 4);
        glGetTextureImage(color, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
        return rgba; // bottom row first
    }
    std::vector<float> readDepth() const {
        std::vector<float> values(std::size_t(kWidth) * kHeight);
        glGetTextureImage(depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                          GLsizei(values.size() * sizeof(float)), values.data());
        return values; // bottom row first
    }
};

glm::mat4 sceneView() {
    return glm::lookAt(glm::vec3(0, 0, 3), glm::vec3(0), glm::vec3(0, 1, 0));
}

// The scene camera's projection in a depth convention: OpenGL's, zero-to-one, reversed-Z
// (zero-to-one with near at 1 and far at 0).
glm::mat4 projection(DepthConvention convention) {
    const float fov = glm::radians(45.0f), aspect = float(kWidth) / float(kHeight);
    const float n = 0.1f, f = 100.0f;
    if (convention == DepthConvention::Default) return glm::perspective(fov, aspect, n, f);
    glm::mat4 p = glm::perspectiveRH_ZO(fov, aspect, n, f);
    if (convention == DepthConvention::ReversedZ) {
        // z' = w - z maps depth d to 1 - d.
        glm::mat4 flip(1.0f);
        flip[2][2] = -1.0f;
        flip[3][2] = 1.0f;
        p = flip * p;
    }
    return p;
}

HostView hostView(DepthConvention convention) {
    HostView view;
    std::memcpy(view.view.data(), glm::value_ptr(sceneView()), sizeof(float) * 16);
    std::memcpy(view.projection.data(), glm::value_ptr(projection(convention)), sizeof(float) * 16);
    view.width = kWidth;
    view.height = kHeight;
    view.depth = convention;
    return view;
}

// The window depth of view depth `z` in a convention.
float windowDepth(DepthConvention convention, float z) {
    const glm::vec4 clip = projection(convention) * glm::vec4(0, 0, -z, 1);
    const float ndc = clip.z / clip.w;
    return convention == DepthConvention::Default ? ndc * 0.5f + 0.5f : ndc;
}

ErrorKind kindOf(const std::function<void()>& call, std::string* message = nullptr) {
    try {
        call();
    } catch (const Error& error) {
        if (message) *message = error.what();
        return error.kind();
    }
    ADD_FAILURE() << "no rmsc::api::Error thrown";
    return ErrorKind::Usage;
}

} // namespace

TEST(Api, BadSceneTextReportsFilePointerAndMessage) {
    const std::string text = R"({"version": 1, "sdf": {"shape": "sphere", "radius": -1}})";
    try {
        Scene::fromJson(text, "bad.json");
        FAIL() << "accepted a negative radius";
    } catch (const Error& error) {
        EXPECT_EQ(error.kind(), ErrorKind::BadInput);
        ASSERT_FALSE(error.problems().empty());
        const Problem& problem = error.problems()[0];
        EXPECT_EQ(problem.file, "bad.json");
        EXPECT_EQ(problem.pointer, "/sdf/radius");
        EXPECT_NE(problem.message.find("-1"), std::string::npos) << problem.message;
        EXPECT_EQ(problem.text(), "bad.json: /sdf/radius: " + problem.message);
        EXPECT_NE(std::string(error.what()).find("bad.json: /sdf/radius: "), std::string::npos);
    }
}

TEST(Api, MissingFileAndValidate) {
    EXPECT_EQ(kindOf([] { Scene::load("no/such/scene.json"); }), ErrorKind::BadInput);
    const std::vector<Problem> problems = Scene::validate("no/such/scene.json");
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0].file, "no/such/scene.json");
    EXPECT_TRUE(Scene::validate(RMSC_TEST_SOURCE_DIR "/samples/scenes/pawn.json").empty());
}

// validateJson reports for text what validate reports for the file holding it, and what
// fromJson refuses it with.
TEST(Api, ValidateJsonAsValidateAFile) {
    const std::string text = R"({"version": 1, "camera": {"fovv": 3, "fov": -3},
                                 "sdf": {"shape": "sphere", "radius": "big"}})";
    const std::string path = ::testing::TempDir() + "rmsc_api_validate.json";
    {
        std::FILE* file = std::fopen(path.c_str(), "wb");
        ASSERT_NE(file, nullptr);
        std::fwrite(text.data(), 1, text.size(), file);
        std::fclose(file);
    }
    const auto lines = [](const std::vector<Problem>& problems) {
        std::vector<std::string> out;
        for (const Problem& problem : problems)
            out.push_back(problem.text());
        return out;
    };
    const std::vector<Problem> fromFile = Scene::validate(path);
    ASSERT_EQ(fromFile.size(), 3u);
    EXPECT_EQ(fromFile[0].severity, Problem::Severity::Warning);
    EXPECT_EQ(fromFile[0].pointer, "/camera/fovv");
    EXPECT_EQ(fromFile[2].pointer, "/sdf/radius");
    EXPECT_EQ(lines(Scene::validateJson(text, path)), lines(fromFile));
    try {
        Scene::fromJson(text, path);
        ADD_FAILURE() << "accepted";
    } catch (const Error& error) {
        EXPECT_EQ(lines(error.problems()), lines(fromFile));
    }
    std::remove(path.c_str());
    // Relative mesh paths resolve against the path given.
    const std::string pawn = RMSC_TEST_SOURCE_DIR "/samples/scenes/pawn.json";
    EXPECT_TRUE(Scene::validateJson(Scene::load(pawn).json(), pawn).empty());
    EXPECT_FALSE(Scene::validateJson(Scene::load(pawn).json(), "elsewhere/pawn.json").empty());
}

TEST(Api, RenderEveryOutput) {
    Scene scene = Scene::fromJson(kSphereScene);
    const Image color = renderer().render(scene, kWidth, kHeight, Aov::Color);
    ASSERT_EQ(color.type, Image::Type::UInt8);
    ASSERT_EQ(color.channels, 3);
    ASSERT_EQ(color.width, kWidth);
    ASSERT_EQ(color.bytes.size(), std::size_t(kWidth) * kHeight * 3);
    const Image depth = renderer().render(scene, kWidth, kHeight, Aov::Depth);
    ASSERT_EQ(depth.type, Image::Type::Float32);
    EXPECT_NEAR(pixel<float>(depth, kWidth / 2, kHeight / 2), 2.0f, 2e-3f); // measured 2e-4
    EXPECT_TRUE(std::isinf(pixel<float>(depth, 0, 0)));
    const Image id = renderer().render(scene, kWidth, kHeight, Aov::Id);
    EXPECT_EQ(pixel<std::uint32_t>(id, kWidth / 2, kHeight / 2), 65536u);
    EXPECT_EQ(pixel<std::uint32_t>(id, 0, 0), 0u);
    const Image normal = renderer().render(scene, kWidth, kHeight, Aov::Normal);
    EXPECT_NEAR(pixel<float>(normal, kWidth / 2, kHeight / 2, 2), 1.0f, 2e-3f); // measured 5e-4
    const Image steps = renderer().render(scene, kWidth, kHeight, Aov::Steps);
    EXPECT_GT(pixel<float>(steps, kWidth / 2, kHeight / 2), 0.0f);
    EXPECT_EQ(parseAov("normal"), Aov::Normal);
    EXPECT_EQ(kindOf([] { parseAov("colour"); }), ErrorKind::Usage);
    EXPECT_EQ(kindOf([&] { renderer().render(scene, 0, 10); }), ErrorKind::Usage);
}

TEST(Api, EditsByPointerCompileNoShadersAfterTheFirst) {
    Scene scene = Scene::fromJson(kSphereScene);
    renderer().compile(scene);
    scene.set("/sdf/radius", "0.5");
    EXPECT_EQ(scene.get("/sdf/radius"), "0.5");
    Image depth = renderer().render(scene, kWidth, kHeight, Aov::Depth);
    EXPECT_NEAR(pixel<float>(depth, kWidth / 2, kHeight / 2), 2.5f, 2e-3f); // measured 5e-4
    // The first edit draws through the buffer map (built once); the next edits compile nothing.
    scene.set("/sdf/position", "[0, 0, 0.25]");
    depth = renderer().render(scene, kWidth, kHeight, Aov::Depth);
    EXPECT_FALSE(renderer().lastStats().compiledShaders);
    EXPECT_NEAR(pixel<float>(depth, kWidth / 2, kHeight / 2), 2.25f, 2e-3f); // measured 4e-4
    scene.set("/materials/clay/base_color", "[0.1, 0.8, 0.2]");
    renderer().render(scene, kWidth, kHeight);
    EXPECT_FALSE(renderer().lastStats().compiledShaders);

    // A bad value: the problem at its pointer, and the scene as it was.
    const std::uint64_t revision = scene.revision();
    try {
        scene.set("/sdf/radius", "-2");
        FAIL() << "accepted a negative radius";
    } catch (const Error& error) {
        EXPECT_EQ(error.kind(), ErrorKind::BadInput);
        ASSERT_FALSE(error.problems().empty());
        EXPECT_EQ(error.problems()[0].pointer, "/sdf/radius");
    }
    EXPECT_EQ(scene.get("/sdf/radius"), "0.5");
    EXPECT_EQ(scene.revision(), revision);
    EXPECT_EQ(kindOf([&] { scene.set("/sdf/nothing/radius", "1"); }), ErrorKind::Usage);
    EXPECT_EQ(kindOf([&] { scene.set("/sdf/radius", "one"); }), ErrorKind::BadInput);
}

// Edits by object id (as the Id output shows it) and by name, beside edits by pointer.
TEST(Api, EditsByNodeIdAndName) {
    Scene scene = Scene::fromJson(R"({
      "version": 1,
      "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov": 45},
      "lights": [{"type": "directional", "name": "sun", "intensity": 3}],
      "sdf": {"op": "union", "name": "pair", "children": [
        {"shape": "sphere", "name": "ball", "radius": 0.5, "position": [-0.7, 0, 0]},
        {"shape": "box", "name": "crate", "half_extents": [0.3, 0.3, 0.3], "position": [0.7, 0, 0]}
      ]}
    })");
    EXPECT_EQ(scene.nodePointer(65536u), "/sdf");
    EXPECT_EQ(scene.nodePointer(65538u), "/sdf/children/1");
    EXPECT_EQ(scene.nodePointer("ball"), "/sdf/children/0");
    EXPECT_EQ(scene.nodePointer("sun"), "/lights/0");
    // The id under a pixel names the node drawn there.
    const Image id = renderer().render(scene, kWidth, kHeight, Aov::Id);
    const std::uint32_t left = pixel<std::uint32_t>(id, kWidth / 2 - 12, kHeight / 2);
    EXPECT_EQ(scene.nodePointer(left), "/sdf/children/0");

    scene.setNode(left, "radius", "0.3");
    EXPECT_EQ(scene.get("/sdf/children/0/radius"), "0.3");
    scene.setNode("crate", "position", "[0.7, 0.2, 0]");
    EXPECT_EQ(scene.get("/sdf/children/1/position"), "[0.7,0.2,0]");
    scene.setNode("sun", "/intensity", "5");
    EXPECT_EQ(scene.get("/lights/0/intensity"), "5");
    const Image depth = renderer().render(scene, kWidth, kHeight, Aov::Depth);
    EXPECT_TRUE(std::isinf(pixel<float>(depth, kWidth / 2 - 12, kHeight / 2 - 8)))
        << "the smaller ball should leave this pixel empty";

    // Bad values: the reader's problem at the node's pointer; the scene as it was.
    const std::uint64_t revision = scene.revision();
    try {
        scene.setNode("crate", "half_extents", "[0.3, -1, 0.3]");
        ADD_FAILURE() << "accepted a negative size";
    } catch (const Error& error) {
        EXPECT_EQ(error.kind(), ErrorKind::BadInput);
        ASSERT_FALSE(error.problems().empty());
        EXPECT_EQ(error.problems()[0].pointer, "/sdf/children/1/half_extents/1");
    }
    EXPECT_EQ(scene.revision(), revision);

    // Unknown ids and names: an error naming them.
    std::string message;
    EXPECT_EQ(kindOf([&] { scene.setNode(65600u, "radius", "1"); }, &message), ErrorKind::Usage);
    EXPECT_NE(message.find("65600"), std::string::npos) << message;
    EXPECT_NE(message.find("65536 to 65538"), std::string::npos) << message;
    EXPECT_EQ(kindOf([&] { scene.nodePointer(0u); }, &message), ErrorKind::Usage);
    EXPECT_EQ(kindOf([&] { scene.setNode("crat", "radius", "1"); }, &message), ErrorKind::Usage);
    EXPECT_NE(message.find("\"crat\""), std::string::npos) << message;
    EXPECT_NE(message.find("\"crate\""), std::string::npos) << message;
    EXPECT_EQ(kindOf([&] { scene.setNode("ball", "", "1"); }), ErrorKind::Usage);
    EXPECT_EQ(kindOf([&] { scene.nodePointer(""); }), ErrorKind::Usage);
    scene.set("/sdf/children/1/name", "\"ball\"");
    EXPECT_EQ(kindOf([&] { scene.nodePointer("ball"); }, &message), ErrorKind::Usage);
    EXPECT_NE(message.find("not unique"), std::string::npos) << message;
}

// A scene built in code is the scene its JSON text gives: the same document, the same picture;
// and a bad value is the reader's problem at the same pointer.
TEST(Api, SceneBuilderMakesTheSceneItsJsonGives) {
    Light sun;
    sun.name = "sun";
    sun.direction = {-0.5f, -1.0f, -0.25f};
    sun.intensity = 2.5f;
    Light lamp;
    lamp.type = Light::Type::Point;
    lamp.position = {1.0f, 1.0f, 2.0f};
    lamp.color = {1.0f, 0.5f, 0.25f};
    lamp.intensity = 10.0f;
    lamp.range = 8.0f;
    SceneBuilder builder;
    builder.camera({{"position", {0, 0.5, 3}}, {"target", {0, 0, 0}}, {"fov", 45}})
        .render({{"background", {0.125, 0.125, 0.25}}})
        .material("clay", {{"base_color", "#e07a5f"}, {"roughness", 0.5}})
        .material("steel", {{"base_color", {0.5, 0.5, 0.75}}, {"metallic", 1}})
        .light(sun)
        .light(lamp)
        .mesh("../assets/plane.gltf", {{"position", {0, -0.75, 0}}, {"scale", 3}})
        .sdf(Node::group("smooth_union",
                         {Node::shape("sphere", {{"radius", 0.5}, {"name", "ball"}}),
                          Node::shape("torus", {{"major_radius", 0.75}, {"minor_radius", 0.125}})
                              .set("material", "steel")
                              .modifier("twist", {{"amount", 30}})},
                         {{"smoothness", 0.25}, {"material", "clay"}})
                 .add(Node::shape("box", {{"half_extents", {0.25, 0.25, 0.25}},
                                          {"position", {0, 0.5, 0}},
                                          {"cut", true}})));
    const std::string text = R"({
      "version": 1,
      "camera": {"position": [0, 0.5, 3], "target": [0, 0, 0], "fov": 45},
      "render": {"background": [0.125, 0.125, 0.25]},
      "materials": {"clay": {"base_color": "#e07a5f", "roughness": 0.5},
                    "steel": {"base_color": [0.5, 0.5, 0.75], "metallic": 1}},
      "lights": [
        {"type": "directional", "name": "sun", "direction": [-0.5, -1, -0.25], "color": [1, 1, 1],
         "intensity": 2.5},
        {"type": "point", "position": [1, 1, 2], "range": 8, "color": [1, 0.5, 0.25],
         "intensity": 10}],
      "meshes": [{"file": "../assets/plane.gltf", "position": [0, -0.75, 0], "scale": 3}],
      "sdf": {"op": "smooth_union", "smoothness": 0.25, "material": "clay", "children": [
        {"shape": "sphere", "radius": 0.5, "name": "ball"},
        {"shape": "torus", "major_radius": 0.75, "minor_radius": 0.125, "material": "steel",
         "modifiers": [{"type": "twist", "amount": 30}]},
        {"shape": "box", "half_extents": [0.25, 0.25, 0.25], "position": [0, 0.5, 0], "cut": true}
      ]}
    })";
    const std::string path = RMSC_TEST_SOURCE_DIR "/samples/scenes/built.json"; // for the mesh
    const Scene built = builder.build(path);
    const Scene read = Scene::fromJson(text, path);
    EXPECT_EQ(built.json(), read.json());
    EXPECT_EQ(Scene::fromJson(builder.json(), path).json(), read.json());
    for (const Aov aov : {Aov::Color, Aov::Id, Aov::Depth}) {
        const Image a = renderer().render(built, kWidth, kHeight, aov);
        const Image b = renderer().render(read, kWidth, kHeight, aov);
        EXPECT_EQ(a.bytes, b.bytes) << "output " << int(aov) << " differs";
        if (aov == Aov::Id) {
            EXPECT_EQ(pixel<std::uint32_t>(a, kWidth / 2, kHeight - 1), 1u); // the mesh
        }
    }
    EXPECT_EQ(built.nodePointer("ball"), "/sdf/children/0");

    // Bad values: the problems the reader gives for the same JSON.
    const auto problemsOf = [](const std::function<void()>& make) {
        try {
            make();
        } catch (const Error& error) {
            EXPECT_EQ(error.kind(), ErrorKind::BadInput);
            return error.problems();
        }
        ADD_FAILURE() << "accepted";
        return std::vector<Problem>{};
    };
    const std::vector<Problem> fromBuilder = problemsOf([] {
        SceneBuilder()
            .sdf(Node::group("union",
                             {Node::shape("sphere"), Node::shape("sphere", {{"radius", -1}}),
                              Node::shape("spere")}))
            .build("built.json");
    });
    const std::vector<Problem> fromText = problemsOf([] {
        Scene::fromJson(R"({"version": 1, "sdf": {"op": "union", "children": [
            {"shape": "sphere"}, {"shape": "sphere", "radius": -1}, {"shape": "spere"}]}})",
                        "built.json");
    });
    ASSERT_EQ(fromBuilder.size(), 2u);
    ASSERT_EQ(fromText.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
        EXPECT_EQ(fromBuilder[i].text(), fromText[i].text());
    EXPECT_EQ(fromBuilder[0].pointer, "/sdf/children/1/radius");
    EXPECT_EQ(fromBuilder[1].pointer, "/sdf/children/2/shape");
    EXPECT_NE(fromBuilder[1].message.find("did you mean \"sphere\""), std::string::npos)
        << fromBuilder[1].text();
    // An unknown operation, a light out of range, a number JSON cannot hold.
    Light dark;
    dark.intensity = -1.0f;
    const std::vector<Problem> more = problemsOf([&] {
        SceneBuilder()
            .light(dark)
            .sdf(Node::group("onion", {Node::shape("box", {{"position", {0, NAN, 0}}})}))
            .build();
    });
    ASSERT_EQ(more.size(), 1u); // the non-finite number first, before the reader runs
    EXPECT_EQ(more[0].pointer, "/sdf/children/0/position/1");
    const std::vector<Problem> reader = problemsOf([&] {
        SceneBuilder().light(dark).sdf(Node::group("onion", {Node::shape("box")})).build();
    });
    ASSERT_EQ(reader.size(), 2u);
    EXPECT_EQ(reader[0].pointer, "/lights/0/intensity");
    EXPECT_EQ(reader[1].pointer, "/sdf/op");
    // Value::json for what the other values cannot say (a profile); text that is not JSON.
    const Scene ring =
        SceneBuilder()
            .sdf(Node::shape("revolution",
                             {{"profile", Value::json(R"({"type": "circle", "radius": 0.2})")},
                              {"offset", 0.5}}))
            .build();
    EXPECT_EQ(ring.get("/sdf/profile/radius"), "0.2");
    const std::vector<Problem> notJson = problemsOf([] {
        SceneBuilder()
            .sdf(Node::shape("revolution", {{"profile", Value::json("{circle}")}}))
            .build();
    });
    ASSERT_EQ(notJson.size(), 1u);
    EXPECT_EQ(notJson[0].pointer, "/sdf/profile");
}

// The builder's lists are the catalogues: every shape they list is read with its parameters at
// their defaults, and every operation they list builds.
TEST(Api, SceneBuilderListsTheCatalogues) {
    const std::vector<ShapeInfo> shapes = SceneBuilder::shapes();
    // A floor against an empty or truncated list (the catalogue holds more than twenty); each
    // name once.
    ASSERT_GT(shapes.size(), 20u);
    std::set<std::string> names;
    for (const ShapeInfo& shape : shapes)
        EXPECT_TRUE(names.insert(shape.name).second) << shape.name << " listed twice";
    EXPECT_EQ(shapes[0].name, "sphere");
    EXPECT_EQ(shapes[0].parameters.at(0).key, "radius");
    for (const ShapeInfo& shape : shapes) {
        Params defaults;
        for (const ShapeParameter& p : shape.parameters)
            if (p.components == 1)
                defaults.emplace_back(p.key, double(p.defaultValue[0]));
            else
                defaults.emplace_back(p.key,
                                      Value({double(p.defaultValue[0]), double(p.defaultValue[1]),
                                             double(p.defaultValue[2])}));
        const std::string json = SceneBuilder().sdf(Node::shape(shape.name, defaults)).json();
        SCOPED_TRACE(shape.name);
        EXPECT_NO_THROW(Scene::fromJson(json));
    }
    const std::vector<std::string> operations = SceneBuilder::operations();
    EXPECT_EQ(operations.front(), "union");
    for (const std::string& operation : operations) {
        SCOPED_TRACE(operation);
        EXPECT_NO_THROW(SceneBuilder()
                            .sdf(Node::group(operation, {Node::shape("sphere"), Node::shape("box")},
                                             {{"smoothness", 0.1}}))
                            .build());
    }
}

// drawInto in each convention: where the sphere is nearer than the host's depth its colour is
// render()'s and its depth is the convention's window depth of view depth 2; elsewhere the
// host's colour and depth stay.
class ApiConventions : public ::testing::TestWithParam<DepthConvention> {};

TEST_P(ApiConventions, DrawIntoHostTextures) {
    const DepthConvention convention = GetParam();
    Scene scene = Scene::fromJson(kSphereScene);
    const Image expected = renderer().render(scene, kWidth, kHeight, Aov::Color);
    const Image id = renderer().render(scene, kWidth, kHeight, Aov::Id);
    if (convention != DepthConvention::Default) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    const bool reversed = convention == DepthConvention::ReversedZ;
    HostTextures host(GL_DEPTH_COMPONENT32F, reversed ? 0.0f : 1.0f);
    // The host's surface: the left half of the image at view depth 1.5, in front of the sphere.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, kWidth / 2, kHeight);
    const float hostDepth = windowDepth(convention, 1.5f);
    glClearNamedFramebufferfv(host.framebuffer, GL_DEPTH, 0, &hostDepth);
    glDisable(GL_SCISSOR_TEST);

    renderer().drawInto(scene, {host.color, host.depth, 0, false}, hostView(convention));
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    const std::vector<std::uint8_t> color = host.readColor();
    const std::vector<float> depth = host.readDepth();
    int sdfPixels = 0, differing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t bottomUp = std::size_t(kHeight - 1 - y) * kWidth + std::size_t(x);
            const std::uint8_t* got = &color[bottomUp * 4];
            const bool sphere = pixel<std::uint32_t>(id, x, y) >= 65536u;
            if (sphere && x >= kWidth / 2) {
                ++sdfPixels;
                for (int c = 0; c < 3; ++c)
                    if (std::abs(int(got[c]) - int(pixel<std::uint8_t>(expected, x, y, c))) > 8) {
                        ++differing;
                        break;
                    }
            } else {
                EXPECT_EQ(got[0], 0);
                EXPECT_EQ(got[2], 255) << "host colour changed at " << x << ", " << y;
            }
        }
    EXPECT_GT(sdfPixels, 100);
    EXPECT_LE(differing, sdfPixels / 200) << differing << " of " << sdfPixels << " differ";
    const std::size_t centreRight = std::size_t(kHeight / 2) * kWidth + std::size_t(kWidth / 2 + 1);
    const float sphereDepthAt = depth[centreRight];
    // Just right of the axis the sphere is a hair farther than 2.
    EXPECT_NEAR(sphereDepthAt, windowDepth(convention, 2.0f), 2e-4f);
    EXPECT_FLOAT_EQ(depth[std::size_t(kHeight / 2) * kWidth + 2], hostDepth);
    EXPECT_FLOAT_EQ(depth[kWidth - 1], reversed ? 0.0f : 1.0f); // bottom right: nothing drawn
}

INSTANTIATE_TEST_SUITE_P(Api, ApiConventions,
                         ::testing::Values(DepthConvention::Default, DepthConvention::ZeroToOne,
                                           DepthConvention::ReversedZ));

TEST(Api, DrawIntoAFramebufferWithADepthStencilTexture) {
    Scene scene = Scene::fromJson(kSphereScene);
    HostTextures host(GL_DEPTH24_STENCIL8, 1.0f);
    HostTarget target;
    target.framebuffer = host.framebuffer;
    renderer().drawInto(scene, target, hostView(DepthConvention::Default));
    const std::vector<std::uint8_t> color = host.readColor();
    const std::size_t centre = std::size_t(kHeight / 2) * kWidth + std::size_t(kWidth / 2);
    EXPECT_NE(color[centre * 4 + 2], 255); // the sphere, not the host's blue
    EXPECT_LT(host.readDepth()[centre], 1.0f);
}

TEST(Api, UnsupportedConventionsAndTargetsAreRefused) {
    Scene scene = Scene::fromJson(kSphereScene);
    HostTextures host(GL_DEPTH_COMPONENT24, 1.0f);
    const HostTarget target{host.color, host.depth, 0, false};
    std::string message;
    // The view says zero-to-one, the context is -1 to 1.
    EXPECT_EQ(
        kindOf([&] { renderer().drawInto(scene, target, hostView(DepthConvention::ZeroToOne)); },
               &message),
        ErrorKind::Usage);
    EXPECT_NE(message.find("GL_NEGATIVE_ONE_TO_ONE"), std::string::npos) << message;
    // Reversed-Z declared for a projection that is not.
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    HostView notReversed = hostView(DepthConvention::ZeroToOne);
    notReversed.depth = DepthConvention::ReversedZ;
    EXPECT_EQ(kindOf([&] { renderer().drawInto(scene, target, notReversed); }, &message),
              ErrorKind::Usage);
    EXPECT_NE(message.find("reversed-Z"), std::string::npos) << message;
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    EXPECT_EQ(
        kindOf([&] { renderer().drawInto(scene, target, hostView(DepthConvention::ZeroToOne)); },
               &message),
        ErrorKind::Usage);
    EXPECT_NE(message.find("GL_UPPER_LEFT"), std::string::npos) << message;
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    // Orthographic.
    HostView ortho = hostView(DepthConvention::Default);
    const glm::mat4 o = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    std::memcpy(ortho.projection.data(), glm::value_ptr(o), sizeof(float) * 16);
    EXPECT_EQ(kindOf([&] { renderer().drawInto(scene, target, ortho); }, &message),
              ErrorKind::Usage);
    EXPECT_NE(message.find("orthographic"), std::string::npos) << message;
    // A colour texture where the depth texture goes.
    EXPECT_EQ(kindOf(
                  [&] {
                      renderer().drawInto(scene, {host.color, host.color, 0, false},
                                          hostView(DepthConvention::Default));
                  },
                  &message),
              ErrorKind::Usage);
    EXPECT_NE(message.find("format"), std::string::npos) << message;
    // A viewport larger than the textures, a name that is no texture.
    HostView large = hostView(DepthConvention::Default);
    large.width = kWidth + 1;
    EXPECT_EQ(kindOf([&] { renderer().drawInto(scene, target, large); }), ErrorKind::Usage);
    EXPECT_EQ(kindOf([&] {
                  renderer().drawInto(scene, {host.color, 987654, 0, false},
                                      hostView(DepthConvention::Default));
              }),
              ErrorKind::Usage);
    // A framebuffer whose depth is a renderbuffer.
    GLuint framebuffer = 0, renderbuffer = 0;
    glCreateFramebuffers(1, &framebuffer);
    glCreateRenderbuffers(1, &renderbuffer);
    glNamedRenderbufferStorage(renderbuffer, GL_DEPTH_COMPONENT24, kWidth, kHeight);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, host.color, 0);
    glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffer);
    HostTarget withRenderbuffer;
    withRenderbuffer.framebuffer = framebuffer;
    EXPECT_EQ(kindOf(
                  [&] {
                      renderer().drawInto(scene, withRenderbuffer,
                                          hostView(DepthConvention::Default));
                  },
                  &message),
              ErrorKind::Usage);
    EXPECT_NE(message.find("renderbuffer"), std::string::npos) << message;
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &renderbuffer);
}

// Host lights: lights equal to the scene's draw what the scene's draw; others change the SDF
// object's shading; the next call without them is lit by the scene's again.
namespace {

// The sphere's pixels drawn into a fresh host (depth 1, blue), RGB top row first, with the
// scene's lights or with `lights`.
std::vector<int> drawnSphere(const Scene& scene, const std::vector<Light>* lights) {
    HostTextures host(GL_DEPTH_COMPONENT24, 1.0f);
    const HostTarget target{host.color, host.depth, 0, false};
    if (lights)
        renderer().drawInto(scene, target, hostView(DepthConvention::Default), *lights);
    else
        renderer().drawInto(scene, target, hostView(DepthConvention::Default));
    const std::vector<std::uint8_t> rgba = host.readColor();
    std::vector<int> rgb;
    for (int y = kHeight - 1; y >= 0; --y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c)
                rgb.push_back(
                    rgba[(std::size_t(y) * kWidth + std::size_t(x)) * 4 + std::size_t(c)]);
    return rgb;
}

// The mean of channel `c` over the pixels where `id` shows the sphere.
double sphereMean(const std::vector<int>& rgb, const Image& id, int c) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (pixel<std::uint32_t>(id, x, y) >= 65536u) {
                sum += rgb[(std::size_t(y) * kWidth + std::size_t(x)) * 3 + std::size_t(c)];
                ++count;
            }
    return count ? sum / count : 0.0;
}

int differingPixels(const std::vector<int>& a, const std::vector<int>& b, int tolerance) {
    int differing = 0;
    for (std::size_t i = 0; i < a.size(); i += 3)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(a[i + c] - b[i + c]) > tolerance) {
                ++differing;
                break;
            }
    return differing;
}

} // namespace

TEST(Api, DrawIntoWithHostLights) {
    Scene scene = Scene::fromJson(kSphereScene);
    const Image id = renderer().render(scene, kWidth, kHeight, Aov::Id);
    const std::vector<int> sceneLit = drawnSphere(scene, nullptr);

    // The scene's light given by the host: the same picture.
    Light sun;
    sun.direction = {-0.3f, -1.0f, -0.6f};
    sun.intensity = 3.0f;
    const std::vector<Light> same = {sun};
    EXPECT_EQ(differingPixels(drawnSphere(scene, &same), sceneLit, 2), 0);

    // A red point light at the front left and a dim spot: the sphere turns red.
    Light red;
    red.type = Light::Type::Point;
    red.position = {-2.0f, 0.5f, 2.0f};
    red.color = {1.0f, 0.1f, 0.1f};
    red.intensity = 30.0f;
    Light spot;
    spot.type = Light::Type::Spot;
    spot.position = {0.0f, 3.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = 5.0f;
    spot.innerAngle = 10.0f;
    spot.outerAngle = 30.0f;
    const std::vector<Light> host = {red, spot};
    const std::vector<int> hostLit = drawnSphere(scene, &host);
    const double sceneRed = sphereMean(sceneLit, id, 0), sceneGreen = sphereMean(sceneLit, id, 1);
    const double hostRed = sphereMean(hostLit, id, 0), hostGreen = sphereMean(hostLit, id, 1);
    // Measured on llvmpipe: red minus green 69.8 scene-lit, 127.2 host-lit (57.4 more).
    EXPECT_GT(hostRed - hostGreen, sceneRed - sceneGreen + 50.0)
        << "scene-lit mean red " << sceneRed << " green " << sceneGreen << "; host-lit red "
        << hostRed << " green " << hostGreen;
    // Only the SDF pixels changed: the host's blue stays around the sphere.
    EXPECT_EQ(hostLit[0], 0);
    EXPECT_EQ(hostLit[2], 255);

    // No lights at all: only the ambient light, darker than either.
    const std::vector<Light> none;
    const std::vector<int> unlit = drawnSphere(scene, &none);
    // Measured: mean red 31.0 unlit against 154.8 scene-lit.
    EXPECT_LT(sphereMean(unlit, id, 0) + 100.0, sceneRed);

    // The next call without host lights, and render(), are lit by the scene's lights again.
    EXPECT_EQ(differingPixels(drawnSphere(scene, nullptr), sceneLit, 0), 0);
    const Image rendered = renderer().render(scene, kWidth, kHeight, Aov::Color);
    const int centre = (kHeight / 2 * kWidth + kWidth / 2) * 3;
    // Measured: the same value (189); one step for rounding between the two paths.
    EXPECT_NEAR(pixel<std::uint8_t>(rendered, kWidth / 2, kHeight / 2), sceneLit[centre], 1);
}

TEST(Api, BadHostLightsAreRefusedAsInAFile) {
    Scene scene = Scene::fromJson(kSphereScene);
    HostTextures host(GL_DEPTH_COMPONENT24, 1.0f);
    const HostTarget target{host.color, host.depth, 0, false};
    const auto problemsOf = [&](const std::vector<Light>& lights) {
        try {
            renderer().drawInto(scene, target, hostView(DepthConvention::Default), lights);
        } catch (const Error& error) {
            EXPECT_EQ(error.kind(), ErrorKind::BadInput);
            return error.problems();
        }
        ADD_FAILURE() << "the lights were accepted";
        return std::vector<Problem>{};
    };
    Light dark;
    dark.intensity = -1.0f;
    std::vector<Problem> problems = problemsOf({Light{}, dark});
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].file, "host lights");
    EXPECT_EQ(problems[0].pointer, "/1/intensity");
    // The reader's message for the same value in a scene file.
    try {
        Scene::fromJson(R"({"version": 1, "lights": [{"type": "directional", "intensity": -1}],
                            "sdf": {"shape": "sphere"}})");
        ADD_FAILURE() << "the scene's light was accepted";
    } catch (const Error& error) {
        ASSERT_FALSE(error.problems().empty());
        EXPECT_EQ(error.problems()[0].pointer, "/lights/0/intensity");
        EXPECT_EQ(problems[0].message, error.problems()[0].message);
    }

    Light cone;
    cone.type = Light::Type::Spot;
    cone.innerAngle = 50.0f;
    cone.outerAngle = 40.0f;
    Light nowhere;
    nowhere.direction = {0.0f, 0.0f, 0.0f};
    Light notANumber;
    notANumber.type = Light::Type::Point;
    notANumber.color = {1.0f, NAN, 1.0f};
    Light negativeRange;
    negativeRange.type = Light::Type::Point;
    negativeRange.range = -2.0f;
    problems = problemsOf({cone, nowhere, notANumber, negativeRange});
    ASSERT_EQ(problems.size(), 4u);
    EXPECT_EQ(problems[0].pointer.rfind("/0/", 0), 0u) << problems[0].text();
    EXPECT_NE(problems[0].message.find("40"), std::string::npos) << problems[0].text();
    EXPECT_EQ(problems[1].pointer, "/1/direction") << problems[1].text();
    EXPECT_EQ(problems[2].pointer, "/2/color/1") << problems[2].text();
    EXPECT_NE(problems[2].message.find("finite"), std::string::npos) << problems[2].text();
    EXPECT_EQ(problems[3].pointer, "/3/range") << problems[3].text();

    // One more than a scene may have.
    problems = problemsOf(std::vector<Light>(17));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].message.find("at most 16"), std::string::npos) << problems[0].text();

    // Nothing was drawn by the refused calls; sixteen lights are drawn.
    const std::size_t centre = std::size_t(kHeight / 2) * kWidth + std::size_t(kWidth / 2);
    EXPECT_EQ(host.readColor()[centre * 4 + 2], 255);
    renderer().drawInto(scene, target, hostView(DepthConvention::Default), std::vector<Light>(16));
    EXPECT_NE(host.readColor()[centre * 4 + 2], 255);
}

namespace {

// The state a host may have set, as glGet reads it back.
std::vector<GLint64> stateSnapshot() {
    std::vector<GLint64> state;
    auto integers = [&](GLenum name, int count) {
        GLint64 values[4] = {};
        glGetInteger64v(name, values);
        state.insert(state.end(), values, values + count);
    };
    for (GLenum capability :
         {GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_BLEND,
          GL_POLYGON_OFFSET_FILL, GL_RASTERIZER_DISCARD, GL_DEPTH_CLAMP, GL_COLOR_LOGIC_OP})
        state.push_back(glIsEnabled(capability));
    for (GLenum name :
         {GL_DRAW_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER_BINDING, GL_CURRENT_PROGRAM,
          GL_VERTEX_ARRAY_BINDING, GL_ARRAY_BUFFER_BINDING, GL_UNIFORM_BUFFER_BINDING,
          GL_SHADER_STORAGE_BUFFER_BINDING, GL_PIXEL_UNPACK_BUFFER_BINDING, GL_ACTIVE_TEXTURE,
          GL_DEPTH_FUNC, GL_DEPTH_WRITEMASK, GL_CULL_FACE_MODE, GL_FRONT_FACE, GL_BLEND_SRC_RGB,
          GL_BLEND_DST_RGB, GL_BLEND_EQUATION_RGB, GL_UNPACK_ALIGNMENT, GL_PACK_ALIGNMENT,
          GL_UNPACK_ROW_LENGTH})
        integers(name, 1);
    integers(GL_VIEWPORT, 4);
    integers(GL_SCISSOR_BOX, 4);
    integers(GL_COLOR_WRITEMASK, 4);
    GLfloat floats[4] = {};
    glGetFloatv(GL_COLOR_CLEAR_VALUE, floats);
    for (float f : floats)
        state.push_back(GLint64(f * 1000));
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, floats);
    state.push_back(GLint64(floats[0] * 1000));
    for (GLuint unit = 0; unit < 18; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        integers(GL_TEXTURE_BINDING_2D, 1);
        integers(GL_TEXTURE_BINDING_BUFFER, 1);
        integers(GL_TEXTURE_BINDING_2D_ARRAY, 1);
        integers(GL_TEXTURE_BINDING_CUBE_MAP, 1);
        integers(GL_SAMPLER_BINDING, 1);
    }
    glActiveTexture(GL_TEXTURE3);
    for (GLuint index = 0; index < 8; ++index) {
        GLint64 value = 0;
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_BINDING, index, &value);
        state.push_back(value);
        if (index < 4) {
            glGetInteger64i_v(GL_UNIFORM_BUFFER_BINDING, index, &value);
            state.push_back(value);
            glGetInteger64i_v(GL_UNIFORM_BUFFER_START, index, &value);
            state.push_back(value);
        }
    }
    return state;
}

} // namespace

TEST(Api, CallsLeaveTheHostsGlStateAsTheyFoundIt) {
    Scene scene = Scene::fromJson(kSphereScene);
    HostTextures host(GL_DEPTH_COMPONENT32F, 1.0f);
    // A host's state, far from the defaults.
    GLuint buffer = 0, texture = 0, sampler = 0, vertexArray = 0, other = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, 1024, nullptr, GL_DYNAMIC_STORAGE_BIT);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_RGBA8, 4, 4);
    glCreateSamplers(1, &sampler);
    glCreateVertexArrays(1, &vertexArray);
    glCreateFramebuffers(1, &other);
    glBindFramebuffer(GL_FRAMEBUFFER, other);
    glBindVertexArray(vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBindBufferRange(GL_UNIFORM_BUFFER, 0, buffer, 256, 256);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, buffer);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
    glBindTextureUnit(0, texture);
    glBindTextureUnit(13, texture);
    glBindTextureUnit(15, texture);
    GLuint texels = 0; // on the units of rmsc's SDF program and cell texels
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &texels);
    glTextureBuffer(texels, GL_R32F, buffer);
    glBindTextureUnit(16, texels);
    glBindTextureUnit(17, texels);
    glBindSampler(4, sampler);
    glActiveTexture(GL_TEXTURE3);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 2, 3, 4);
    glViewport(5, 6, 7, 8);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_MAX);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CW);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(3, 4);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
    const std::vector<GLint64> before = stateSnapshot();

    renderer().drawInto(scene, {host.color, host.depth, 0, false},
                        hostView(DepthConvention::Default));
    EXPECT_EQ(stateSnapshot(), before) << "after drawInto";
    Scene edited = Scene::fromJson(kSphereScene);
    edited.set("/sdf/radius", "0.75");
    renderer().compile(edited);
    renderer().render(edited, 16, 16, Aov::Depth);
    EXPECT_EQ(stateSnapshot(), before) << "after compile and render";
    // More shapes than generated code takes (limits::kGeneratedCodeShapes, 160): drawn with the
    // cells map, which binds the cell table's texels too.
    std::string many = R"({"version": 1, "sdf": {"children": [)";
    for (int i = 0; i < 200; ++i)
        many += std::string(i ? ", " : "") +
                R"({"shape": "sphere", "radius": 0.05, "position": [)" +
                std::to_string(0.1 * (i % 20) - 1.0) + ", " + std::to_string(0.1 * (i / 20) - 0.5) +
                ", 0]}";
    many += "]}}";
    renderer().render(Scene::fromJson(many), 16, 16, Aov::Depth);
    EXPECT_EQ(stateSnapshot(), before) << "after a scene drawn with the cells map";
    GLint polygonMode[2] = {};
    glGetIntegerv(GL_POLYGON_MODE, polygonMode);
    EXPECT_EQ(polygonMode[0], GL_LINE);
    // The SDF still drew: the host's colour mask and scissor did not stop it.
    const std::vector<std::uint8_t> color = host.readColor();
    const std::size_t centre = std::size_t(kHeight / 2) * kWidth + std::size_t(kWidth / 2);
    EXPECT_NE(color[centre * 4 + 2], 255);

    // Back to defaults for the other tests.
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
    for (GLuint unit : {0u, 13u, 15u, 16u, 17u})
        glBindTextureUnit(unit, 0);
    glBindSampler(4, 0);
    glDeleteFramebuffers(1, &other);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteSamplers(1, &sampler);
    glDeleteTextures(1, &texture);
    glDeleteTextures(1, &texels);
    glDeleteBuffers(1, &buffer);
}

// Runs last in the file (gtest keeps the order): it switches and releases contexts.
TEST(Api, ZContextMisuseIsAnErrorNotACrash) {
    Scene scene = Scene::fromJson(kSphereScene);
    Renderer& first = renderer();
    {
        HeadlessContext second(parseBackend(context().backend())); // current now
        std::string message;
        EXPECT_EQ(kindOf([&] { first.render(scene, 8, 8); }, &message), ErrorKind::Context);
        EXPECT_NE(message.find("not the one this Renderer was made on"), std::string::npos)
            << message;
        Renderer own; // works on the second context
        EXPECT_EQ(own.render(scene, 8, 8).width, 8);
        context().makeCurrent();
        EXPECT_EQ(kindOf([&] { own.render(scene, 8, 8); }), ErrorKind::Context);
        second.makeCurrent();
    } // `own` and `second` go with the second context current
    context().makeCurrent();
    EXPECT_EQ(first.render(scene, 8, 8).width, 8);

    // No context at all.
    const std::string backend = context().backend();
    if (backend == "egl")
        eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    else
        OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    std::string message;
    EXPECT_EQ(kindOf([] { Renderer none; }, &message), ErrorKind::Context);
    EXPECT_NE(message.find("no OpenGL context is current"), std::string::npos) << message;
    EXPECT_EQ(kindOf([&] { first.render(scene, 8, 8); }), ErrorKind::Context);
    context().makeCurrent();
    EXPECT_EQ(first.render(scene, 8, 8).width, 8);
}
