// The GLSL generated from compiled SDF programs (sdf/glsl_codegen.hpp), checked as text: which
// strategy's text changes with which edit, literals that read back exactly, and the fallback
// of very large scenes to the interpreter. That the code draws the right image is checked by
// the GPU tests (test_sdf_strategies.cpp).
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/glsl_codegen.hpp"

#include "sdf_text.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace rmsc;

namespace {

const char* kTwoShapes = R"({"op": "smooth_union", "smoothness": 0.3, "children": [
    {"shape": "sphere", "radius": 0.5, "position": [1, 0, 0]},
    {"shape": "torus", "major_radius": 0.6, "minor_radius": 0.1,
     "modifiers": [{"type": "twist", "amount": 45, "radius": 0.7}]}]})";

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

} // namespace

TEST(GlslCodegen, BakedCodeCallsOnlyTheUsedPrimitivesWithLiterals) {
    const std::string map = generateSdfMap(test::compileSdfText(kTwoShapes), SdfStrategy::Baked);
    EXPECT_EQ(count(map, "sdSphere("), 2u); // once in sdfDistance, once in sdfSurface
    EXPECT_EQ(count(map, "sdTorus("), 2u);
    EXPECT_EQ(count(map, "sdBox("), 0u);
    EXPECT_EQ(count(map, "Instructions["), 0u) << "baked code reads no buffer";
    EXPECT_NE(map.find("sdSphere(q"), std::string::npos);
    EXPECT_NE(map.find(", 0.5)"), std::string::npos) << map; // the radius as a literal
    EXPECT_NE(map.find("sdfPointModifier("), std::string::npos) << "the twist";
    EXPECT_NE(map.find("bool sdfSceneEmpty() { return false; }"), std::string::npos);
}

TEST(GlslCodegen, BufferCodeKeepsItsTextUnderParameterEdits) {
    const SdfProgram program = test::compileSdfText(kTwoShapes);
    SdfProgram edited =
        test::compileSdfText(R"({"op": "smooth_union", "smoothness": 0.1, "children": [
        {"shape": "sphere", "radius": 0.9, "position": [0, 2, 0], "rotation": [10, 0, 0]},
        {"shape": "torus", "major_radius": 0.2, "minor_radius": 0.05,
         "modifiers": [{"type": "twist", "amount": 10, "radius": 0.25}]}]})");
    EXPECT_EQ(generateSdfMap(program, SdfStrategy::Buffer),
              generateSdfMap(edited, SdfStrategy::Buffer));
    EXPECT_NE(generateSdfMap(program, SdfStrategy::Baked),
              generateSdfMap(edited, SdfStrategy::Baked));
    // Another operation is another structure.
    const SdfProgram other = test::compileSdfText(R"({"op": "union", "children": [
        {"shape": "sphere", "radius": 0.5}, {"shape": "torus", "major_radius": 0.6,
         "minor_radius": 0.1, "modifiers": [{"type": "twist", "amount": 45, "radius": 0.7}]}]})");
    EXPECT_NE(generateSdfMap(program, SdfStrategy::Buffer),
              generateSdfMap(other, SdfStrategy::Buffer));
}

TEST(GlslCodegen, LiteralsReadBackExactly) {
    const SdfProgram program = test::compileSdfText(
        R"({"shape": "sphere", "radius": 0.1234567, "position": [0.3, -1e-7, 12345.678]})");
    const std::string map = generateSdfMap(program, SdfStrategy::Baked);
    const float radius = program.instructions[0].params[0].x;
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(radius));
    EXPECT_NE(map.find(text), std::string::npos) << map;
    EXPECT_EQ(std::stof(text), radius);
    // Whole numbers still read as floats in GLSL (an int literal would not convert inside
    // vec4(...) overload resolution everywhere): the scale of 1 is written "1.0".
    EXPECT_NE(map.find(" * 1.0;"), std::string::npos) << map;
}

TEST(GlslCodegen, EmptySceneNeverHits) {
    const std::string map = generateSdfMap(SdfProgram{}, SdfStrategy::Baked);
    EXPECT_NE(map.find("bool sdfSceneEmpty() { return true; }"), std::string::npos);
    EXPECT_NE(map.find("return SDF_FAR;"), std::string::npos);
}

TEST(GlslCodegen, VeryLargeScenesFallBackToCells) {
    std::string children;
    for (int i = 0; i <= kMaxGeneratedLeaves; ++i)
        children += std::string(i ? ", " : "") +
                    R"({"shape": "sphere", "radius": 0.1, "position": [)" + std::to_string(i) +
                    ", 0, 0]}";
    const SdfProgram large = test::compileSdfText(R"({"children": [)" + children + "]}");
    EXPECT_EQ(effectiveSdfStrategy(large, SdfStrategy::Baked), SdfStrategy::Cells);
    const std::string map = generateSdfMap(large, SdfStrategy::Baked);
    // (the stackless loop of the cells: a union of shapes is box tests and parts)
    EXPECT_NE(map.find("#define SDF_CELLS_LEAN 1"), std::string::npos);
    EXPECT_NE(map.find("#include \"common/sdf_cells.glsl\""), std::string::npos);
    // Its dispatch holds only the kinds the scene uses, and the plane of the far cells.
    EXPECT_NE(map.find("sdSphere("), std::string::npos);
    EXPECT_NE(map.find("sdPlane("), std::string::npos);
    EXPECT_EQ(map.find("sdBox("), std::string::npos);
    // The interpreter when asked for.
    EXPECT_NE(generateSdfMap(large, SdfStrategy::Interpreter)
                  .find("#include \"common/sdf_parts_loop.glsl\""),
              std::string::npos);
    EXPECT_EQ(effectiveSdfStrategy(test::compileSdfText(kTwoShapes), SdfStrategy::Baked),
              SdfStrategy::Baked);
}

// The editing map: baked, but the objects being edited read the buffer. Their edits keep the
// text; an edit anywhere else changes it.
TEST(GlslCodegen, LiveObjectsReadTheBufferAndKeepTheTextUnderTheirEdits) {
    const char* scene = R"({"op": "smooth_union", "smoothness": 0.3, "children": [
        {"shape": "sphere", "radius": 0.5, "position": [1, 0, 0]},
        {"op": "union", "position": [0, 1, 0], "children": [
            {"shape": "box", "size": [0.2, 0.3, 0.4]},
            {"shape": "torus", "major_radius": 0.6, "minor_radius": 0.1}]}]})";
    const SdfProgram program = test::compileSdfText(scene);
    // Pre-order: root 0, sphere 1, group 2, box 3, torus 4; the group's subtree is 2..4.
    const SdfLiveRange group{kSdfIdBase + 2, kSdfIdBase + 4};
    const std::string map = generateSdfMap(program, SdfStrategy::Baked, {}, group);
    EXPECT_EQ(count(map, "sdBox(q"), 2u);
    EXPECT_NE(map.find(", 0.5)"), std::string::npos) << "the sphere stays baked:\n" << map;
    std::size_t liveInstructions = 0;
    for (std::size_t i = 0; i < program.instructions.size(); ++i) {
        const bool live = group.contains(program.instructions[i].objectId);
        liveInstructions += live;
        const std::string read = "sdfUniformInstructions[" + std::to_string(i) + "]";
        EXPECT_EQ(map.find(read) != std::string::npos, live)
            << "instruction " << i << " (object " << program.instructions[i].objectId << ")";
    }
    EXPECT_EQ(liveInstructions, 3u) << "box, torus and the group's union";

    // Moving the group and resizing the box (its subtree) keeps the text.
    const SdfProgram editedInside =
        test::compileSdfText(R"({"op": "smooth_union", "smoothness": 0.3,
        "children": [{"shape": "sphere", "radius": 0.5, "position": [1, 0, 0]},
        {"op": "union", "position": [2, 1, 0], "rotation": [0, 30, 0], "children": [
            {"shape": "box", "size": [0.7, 0.3, 0.4]},
            {"shape": "torus", "major_radius": 0.6, "minor_radius": 0.1}]}]})");
    EXPECT_EQ(generateSdfMap(editedInside, SdfStrategy::Baked, {}, group), map);
    // The sphere is outside it: editing the sphere is new code.
    const SdfProgram editedOutside =
        test::compileSdfText(R"({"op": "smooth_union", "smoothness": 0.3,
        "children": [{"shape": "sphere", "radius": 0.6, "position": [1, 0, 0]},
        {"op": "union", "position": [0, 1, 0], "children": [
            {"shape": "box", "size": [0.2, 0.3, 0.4]},
            {"shape": "torus", "major_radius": 0.6, "minor_radius": 0.1}]}]})");
    EXPECT_NE(generateSdfMap(editedOutside, SdfStrategy::Baked, {}, group), map);
    // The smooth union is the root's, outside the range: its k is a literal.
    EXPECT_NE(map.find("vec4(0.300000012"), std::string::npos) << map;

    // Without a range, the map is the plain baked one; the buffer strategy ignores the range.
    EXPECT_EQ(count(generateSdfMap(program, SdfStrategy::Baked, {}, {}), "Instructions["), 0u);
    EXPECT_EQ(generateSdfMap(program, SdfStrategy::Buffer, {}, group),
              generateSdfMap(program, SdfStrategy::Buffer));
}

// Generated code reads the buffer's uniform window where it reaches (kSdfUniformInstructions),
// the storage buffer past it (a shell's map starting far into the buffer).
TEST(GlslCodegen, BufferReadsUseTheUniformWindowWhereItReaches) {
    const SdfProgram program = test::compileSdfText(kTwoShapes);
    const std::string near = generateSdfMap(program, SdfStrategy::Buffer);
    EXPECT_NE(near.find("sdfUniformInstructions[0]."), std::string::npos) << near;
    EXPECT_EQ(count(near, "sdfInstructions["), 0u);
    const std::size_t base = std::size_t(kSdfUniformInstructions) - 1;
    const std::string far = generateSdfMap(program, SdfStrategy::Buffer, {"shell", base});
    EXPECT_NE(far.find("sdfUniformInstructions[" + std::to_string(base) + "]"), std::string::npos);
    EXPECT_NE(far.find("sdfInstructions[" + std::to_string(base + 1) + "]"), std::string::npos)
        << far;
    EXPECT_EQ(count(far, "Instructions[" + std::to_string(base - 1) + "]"), 0u);
}

// The interpreter strategy: the lean loop for programs of box tests and one-shape parts (what
// large unions compile to), the generic interpreter for anything else.
TEST(GlslCodegen, PartsOnlyProgramsGetTheLeanInterpreter) {
    std::string children;
    for (int i = 0; i < 6; ++i)
        children += std::string(i ? ", " : "") +
                    R"({"shape": "sphere", "radius": 0.1, "position": [)" + std::to_string(i) +
                    ", 0, 0]}";
    const SdfProgram parts = test::compileSdfText(R"({"children": [)" + children + "]}");
    const std::string lean = generateSdfMap(parts, SdfStrategy::Interpreter);
    EXPECT_NE(lean.find("common/sdf_parts_loop.glsl"), std::string::npos) << lean;
    EXPECT_EQ(lean.find("common/sdf_interpreter.glsl"), std::string::npos);
    const std::string generic =
        generateSdfMap(test::compileSdfText(kTwoShapes), SdfStrategy::Interpreter);
    EXPECT_NE(generic.find("common/sdf_interpreter.glsl"), std::string::npos) << generic;
    EXPECT_EQ(generic.find("sdf_parts_loop"), std::string::npos);
}
