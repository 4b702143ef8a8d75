// Shells (SdfNode::shell) without GL: the scene format reads and writes them, the compiler
// splits them from the fullscreen program with their ids and frames, wrong placements and
// unbounded or broken proxies are refused at the right JSON pointer, and the proxy meshes
// enclose what they must.
#include "prepare/prepared_scene.hpp"
#include "prepare/shell_proxy.hpp"
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;

namespace {

std::string withSdf(const std::string& sdf) {
    return R"({"version": 1, "materials": {"red": {}}, "sdf": )" + sdf + "}";
}

// Prepares `text` as if it were samples/scenes/test.json (so "../assets/..." resolves).
std::optional<PreparedScene> prepareText(const std::string& text, Diagnostics& diagnostics) {
    const std::filesystem::path path =
        std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "samples" / "scenes" / "test.json";
    std::optional<Scene> scene = parseScene(text, path, diagnostics);
    if (!scene) return std::nullopt;
    return prepareScene(std::move(*scene), diskFileSource(), diagnostics);
}

// `text` must fail to prepare with an error at `location` whose message contains `words`.
void expectRefused(const std::string& text, const std::string& location, const std::string& words) {
    Diagnostics d;
    EXPECT_FALSE(prepareText(text, d)) << text;
    bool found = false;
    for (const Diagnostic& item : d.items)
        found =
            found || (item.severity == Severity::Error && item.location.rfind(location, 0) == 0 &&
                      item.message.find(words) != std::string::npos);
    EXPECT_TRUE(found) << "expected an error at " << location << " containing \"" << words
                       << "\", got:\n"
                       << d.format();
}

// Signed volume of a closed triangle mesh (divergence theorem): > 0 when every triangle is
// counter-clockwise seen from outside.
double signedVolume(const ShellProxyMesh& mesh) {
    double volume = 0.0;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
            c(mesh.positions[mesh.indices[i + 2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

// Is p inside the convex mesh (behind every face's plane)?
bool insideConvex(const ShellProxyMesh& mesh, glm::vec3 p) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[i]],
                        b = mesh.positions[mesh.indices[i + 1]],
                        c = mesh.positions[mesh.indices[i + 2]];
        if (glm::dot(glm::cross(b - a, c - a), p - a) > 1e-5f) return false;
    }
    return true;
}

} // namespace

TEST(ShellScene, ReadsAndWritesTheShellObject) {
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(withSdf(R"({"op": "union", "children": [
            {"shape": "sphere", "shell": true},
            {"shape": "plane", "shell": {"proxy": "sphere", "bound": [2, 0.5, 2]}},
            {"shape": "box", "shell": {"proxy": "mesh", "mesh": "hull.gltf"}},
            {"shape": "torus", "shell": false}]})"),
                                                  "/scenes/a.json", d);
    ASSERT_TRUE(scene) << d.format();
    const std::vector<SdfNode>& c = scene->sdf->children;
    ASSERT_TRUE(c[0].shell);
    EXPECT_EQ(c[0].shell->proxy, ShellProxy::Box);
    EXPECT_EQ(c[0].shell->pointer, "/sdf/children/0/shell");
    ASSERT_TRUE(c[1].shell && c[1].shell->bound);
    EXPECT_EQ(c[1].shell->proxy, ShellProxy::Sphere);
    EXPECT_EQ(*c[1].shell->bound, glm::vec3(2.0f, 0.5f, 2.0f));
    ASSERT_TRUE(c[2].shell);
    EXPECT_EQ(c[2].shell->proxy, ShellProxy::Mesh);
    EXPECT_EQ(c[2].shell->meshPath, std::filesystem::path("/scenes/hull.gltf"));
    EXPECT_FALSE(c[3].shell);

    // Written and read back: the same shells.
    Diagnostics again;
    const std::optional<Scene> reread = parseScene(sceneToJson(*scene), "/scenes/a.json", again);
    ASSERT_TRUE(reread) << again.format();
    for (std::size_t i = 0; i < c.size(); ++i) {
        const std::optional<SdfShell>& a = c[i].shell;
        const std::optional<SdfShell>& b = reread->sdf->children[i].shell;
        ASSERT_EQ(a.has_value(), b.has_value()) << i;
        if (!a) continue;
        EXPECT_EQ(a->proxy, b->proxy);
        EXPECT_EQ(a->bound, b->bound);
        EXPECT_EQ(a->meshFile, b->meshFile);
    }
}

TEST(ShellScene, BadShellObjectsNameTheirPointer) {
    Diagnostics d;
    EXPECT_FALSE(
        parseScene(withSdf(R"({"shape": "sphere", "shell": {"proxy": "cone"}})"), "bad.json", d));
    EXPECT_NE(d.format().find("/sdf/shell/proxy"), std::string::npos) << d.format();
    EXPECT_NE(d.format().find("\"box\", \"sphere\", \"mesh\""), std::string::npos) << d.format();
    Diagnostics noMesh;
    EXPECT_FALSE(parseScene(withSdf(R"({"shape": "sphere", "shell": {"proxy": "mesh"}})"),
                            "bad.json", noMesh));
    EXPECT_NE(noMesh.format().find("/sdf/shell"), std::string::npos) << noMesh.format();
    Diagnostics badBound;
    EXPECT_FALSE(parseScene(withSdf(R"({"shape": "sphere", "shell": {"bound": [1, 0, 1]}})"),
                            "bad.json", badBound));
    EXPECT_NE(badBound.format().find("/sdf/shell/bound/1"), std::string::npos) << badBound.format();
    Diagnostics wrongType;
    EXPECT_FALSE(parseScene(withSdf(R"({"shape": "sphere", "shell": 1})"), "bad.json", wrongType));
    EXPECT_NE(wrongType.format().find("/sdf/shell"), std::string::npos) << wrongType.format();
}

// The shell leaves the fullscreen program; its own program, in the node's frame and with the
// ids the nodes have in the whole tree, gives the whole tree's distances where it is nearest.
TEST(ShellCompiler, SplitsShellsWithTheirIdsAndFrames) {
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(withSdf(R"({"op": "union", "children": [
            {"shape": "box", "position": [-2, 0, 0]},
            {"op": "union", "position": [1, 0.5, 0], "rotation": [0, 40, 0], "scale": 2, "shell": true,
             "children": [{"shape": "sphere", "radius": 0.3}, {"shape": "torus", "position": [0.2, 0, 0]}]},
            {"shape": "capsule"}]})"),
                                                  "a.json", d);
    ASSERT_TRUE(scene) << d.format();
    const std::optional<CompiledSdfScene> split = compileSdfScene(*scene->sdf, 1, "a.json", d);
    const std::optional<SdfProgram> whole = compileSdf(*scene->sdf, 1, "a.json", d);
    ASSERT_TRUE(split && whole) << d.format();
    ASSERT_EQ(split->shells.size(), 1u);
    EXPECT_EQ(split->main.nodePointers.size(), 6u); // every node keeps its id
    const SdfShellProgram& shell = split->shells[0];
    EXPECT_EQ(shell.pointer, "/sdf/children/1");
    EXPECT_FLOAT_EQ(shell.distanceScale, 2.0f);
    // Shapes: box (id 1) and capsule (id 5) in the main program, sphere (3) and torus (4) in
    // the shell.
    std::vector<std::uint32_t> mainIds, shellIds;
    for (const GpuSdfInstruction& in : split->main.instructions)
        if (SdfOpcode(in.opcode) == SdfOpcode::Shape) mainIds.push_back(in.objectId - kSdfIdBase);
    for (const GpuSdfInstruction& in : shell.program.instructions)
        if (SdfOpcode(in.opcode) == SdfOpcode::Shape) shellIds.push_back(in.objectId - kSdfIdBase);
    std::sort(mainIds.begin(), mainIds.end());
    std::sort(shellIds.begin(), shellIds.end());
    EXPECT_EQ(mainIds, (std::vector<std::uint32_t>{1, 5}));
    EXPECT_EQ(shellIds, (std::vector<std::uint32_t>{3, 4}));
    // min(main, shell at the object point) is the whole tree's distance, everywhere.
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 p(std::sin(i * 1.7f) * 3.0f, std::cos(i * 0.9f) * 1.5f,
                          std::sin(i * 0.37f) * 2.0f);
        const glm::vec3 q = glm::vec3(shell.worldToObject * glm::vec4(p, 1.0f));
        const float combined = std::min(sdfDistance(split->main, p), sdfDistance(shell.program, q));
        EXPECT_NEAR(combined, sdfDistance(*whole, p), 1e-4f * std::max(1.0f, std::abs(combined)))
            << "at " << p.x << ", " << p.y << ", " << p.z;
    }
}

TEST(ShellCompiler, RefusesShellsThatCannotMeetTheSceneThroughDepth) {
    expectRefused(withSdf(R"({"op": "smooth_union", "smoothness": 0.2, "children": [
                     {"shape": "sphere", "shell": true}, {"shape": "box"}]})"),
                  "/sdf/children/0/shell", "smooth union");
    expectRefused(withSdf(R"({"op": "union", "modifiers": [{"type": "round", "radius": 0.1}],
                     "children": [{"shape": "sphere", "shell": true}, {"shape": "box"}]})"),
                  "/sdf/children/0/shell", "modifiers");
    expectRefused(withSdf(R"({"op": "union", "children": [
                     {"shape": "sphere", "shell": true}, {"shape": "box", "cut": true}, {"shape": "torus"}]})"),
                  "/sdf/children/0/shell", "\"cut\" child");
    expectRefused(withSdf(R"({"op": "union", "children": [
                     {"shape": "sphere", "shell": true, "cut": true}, {"shape": "box"}]})"),
                  "/sdf/children/0/shell", "cannot be \"cut\"");
    expectRefused(withSdf(R"({"op": "union", "shell": true, "children": [
                     {"shape": "sphere", "shell": true}, {"shape": "box"}]})"),
                  "/sdf/children/0/shell", "a shell inside a shell");
}

TEST(ShellProxies, UnboundedContentNeedsABoundOrAMesh) {
    expectRefused(withSdf(R"({"shape": "plane", "shell": true})"), "/sdf/shell",
                  "reaches infinity");
    expectRefused(withSdf(R"({"shape": "sphere", "radius": 0.2, "shell": true,
                              "modifiers": [{"type": "repeat", "period": [1, 0, 1]}]})"),
                  "/sdf/shell", "/sdf/modifiers/0");
    Diagnostics d;
    const std::optional<PreparedScene> clamped =
        prepareText(withSdf(R"({"shape": "plane", "shell": {"bound": [2, 0.5, 3]}})"), d);
    ASSERT_TRUE(clamped) << d.format();
    ASSERT_EQ(clamped->shells.size(), 1u);
    EXPECT_EQ(clamped->shells[0].clipMax, glm::vec3(2.0f, 0.5f, 3.0f));
    EXPECT_EQ(clamped->shells[0].clipMin, glm::vec3(-2.0f, -0.5f, -3.0f));
}

TEST(ShellProxies, AMissingOrBrokenProxyMeshIsAnErrorAtItsPointer) {
    expectRefused(
        withSdf(
            R"({"shape": "sphere", "shell": {"proxy": "mesh", "mesh": "../assets/none.gltf"}})"),
        "/sdf/shell/mesh", "none.gltf");
    expectRefused(withSdf(R"({"op": "union", "children": [{"shape": "box"},
                     {"shape": "sphere", "shell": {"proxy": "mesh", "mesh": "test.json"}}]})"),
                  "/sdf/children/1/shell/mesh", "test.json");
}

TEST(ShellProxies, TheProxyBoxHoldsTheContentWithAMargin) {
    Diagnostics d;
    const std::optional<PreparedScene> prepared = prepareText(
        withSdf(R"({"shape": "box", "half_extents": [0.5, 0.2, 0.3], "position": [4, 0, 0],
                    "scale": 3, "shell": true})"),
        d);
    ASSERT_TRUE(prepared) << d.format();
    const PreparedShell& shell = prepared->shells[0];
    // Object space: the node's own frame, so the box is about the content's own extents.
    for (int axis = 0; axis < 3; ++axis) {
        const float half = glm::vec3(0.5f, 0.2f, 0.3f)[axis];
        EXPECT_GT(shell.clipMax[axis], half);
        EXPECT_LT(shell.clipMax[axis], half * 1.1f + 0.01f);
        EXPECT_LT(shell.clipMin[axis], -half);
    }
    EXPECT_EQ(shell.proxy.positions.size(), 8u);
}

TEST(ShellProxies, BoxAndSphereMeshesAreClosedOutwardAndEncloseTheBox) {
    const glm::vec3 lo(-1.0f, -0.2f, 0.5f), hi(2.0f, 0.6f, 0.9f);
    for (const ShellProxyMesh& mesh : {boxProxyMesh(lo, hi), sphereProxyMesh(lo, hi)}) {
        EXPECT_GT(signedVolume(mesh), (hi - lo).x * (hi - lo).y * (hi - lo).z * 0.999);
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
            EXPECT_TRUE(insideConvex(mesh, corner)) << "corner " << c;
        }
    }
    // The sphere's faces clear the sphere through the corners, but not by much.
    const ShellProxyMesh sphere = sphereProxyMesh(lo, hi);
    const float radius = 0.5f * glm::length(hi - lo);
    const glm::vec3 centre = 0.5f * (lo + hi);
    for (int i = 0; i < 100; ++i) {
        const glm::vec3 dir = glm::normalize(
            glm::vec3(std::sin(i * 2.1f), std::cos(i * 1.3f), std::sin(i * 0.7f + 1.0f)));
        EXPECT_TRUE(insideConvex(sphere, centre + dir * radius * 0.999f));
        EXPECT_FALSE(insideConvex(sphere, centre + dir * radius * 1.2f));
    }
}
