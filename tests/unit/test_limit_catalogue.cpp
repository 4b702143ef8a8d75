// The limit catalogue (core/limit_catalogue.hpp): one row for every constant of core/limits.hpp,
// docs/limits.md's table equal to its markdown, the value texts, and the other layers' names and
// the shaders' fixed arrays agreeing with the constants.
#include "core/limit_catalogue.hpp"
#include "core/limits.hpp"
#include "sdf/compiler.hpp"
#include "sdf/glsl_codegen.hpp"
#include "sdf/glsl_constants.hpp"
#include "sdf/program.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace rmsc;

namespace {

std::string readSourceFile(const std::string& relativePath) {
    std::ifstream file(std::string(RMSC_TEST_SOURCE_DIR) + "/" + relativePath);
    std::stringstream buffer;
    buffer << file.rdbuf();
    return buffer.str();
}

const Limit& row(const std::string& constant) {
    for (const Limit& limit : limitCatalogue())
        if (limit.constant == constant) return limit;
    ADD_FAILURE() << "no row for " << constant;
    return limitCatalogue().front();
}

} // namespace

TEST(LimitCatalogue, EveryConstantHasOneRow) {
    const std::string header = readSourceFile("engine/core/include/core/limits.hpp");
    ASSERT_FALSE(header.empty()) << "engine/core/include/core/limits.hpp is missing";
    std::set<std::string> constants;
    const std::regex definition(R"(constexpr [^=;]* (k\w+) =)");
    for (std::sregex_iterator it(header.begin(), header.end(), definition), end; it != end; ++it)
        constants.insert((*it)[1]);
    EXPECT_GT(constants.size(), 20u);

    std::set<std::string> rows;
    for (const Limit& limit : limitCatalogue()) {
        EXPECT_TRUE(rows.insert(limit.constant).second) << "two rows for " << limit.constant;
        EXPECT_TRUE(*limit.name && *limit.bounds && *limit.exceeded) << limit.constant;
        EXPECT_GT(limit.value, 0.0) << limit.constant;
    }
    EXPECT_EQ(rows, constants) << "every constant of core/limits.hpp needs one catalogue row, "
                                  "and every row names a constant there";
}

TEST(LimitCatalogue, RowsHoldTheConstantsThatTheLayersUse) {
    EXPECT_EQ(row("kSceneFileBytes").value, double(limits::kSceneFileBytes));
    EXPECT_EQ(row("kGltfIndices").value, double(limits::kGltfIndices));
    EXPECT_EQ(row("kSdfStack").value, kSdfMaxStack);
    EXPECT_EQ(row("kSdfPointStack").value, kSdfMaxPointStack);
    EXPECT_EQ(row("kSdfInstructions").value, kSdfMaxInstructions);
    EXPECT_EQ(row("kSdfData").value, kSdfMaxData);
    EXPECT_EQ(row("kShellShapes").value, kMaxShellShapes);
    EXPECT_EQ(row("kGeneratedCodeShapes").value, kMaxGeneratedLeaves);
}

// The shaders' stack sizes come from generated/constants.glsl (sdf/glsl_constants.hpp), made
// from the limits; no shader source writes them itself.
TEST(LimitCatalogue, ShaderArraysHaveTheSizesOfTheLimits) {
    const std::string generated = glslDefines(sdfGlslConstants());
    EXPECT_NE(generated.find("#define SDF_MAX_STACK " + std::to_string(limits::kSdfStack) + "\n"),
              std::string::npos);
    EXPECT_NE(generated.find("#define SDF_MAX_POINT_STACK " +
                             std::to_string(limits::kSdfPointStack) + "\n"),
              std::string::npos);
    const std::string glsl = readSourceFile("shaders/common/sdf_functions.glsl");
    ASSERT_FALSE(glsl.empty());
    EXPECT_EQ(glsl.find("#define SDF_MAX_STACK"), std::string::npos);
    EXPECT_EQ(glsl.find("#define SDF_MAX_POINT_STACK"), std::string::npos);
    EXPECT_NE(glsl.find("#include \"generated/constants.glsl\""), std::string::npos);
}

TEST(LimitCatalogue, ValuesReadWithTheirUnits) {
    EXPECT_EQ(limitValueText(row("kSceneFileBytes")), "64 MiB (67108864 bytes)");
    EXPECT_EQ(limitValueText(row("kInputFileBytes")), "1 GiB (1073741824 bytes)");
    EXPECT_EQ(limitValueText(row("kGltfIndices")), "50331648 (48 Mi)");
    EXPECT_EQ(limitValueText(row("kRepeatCopies")), "1048576 (1 Mi) per axis");
    EXPECT_EQ(limitValueText(row("kSceneJsonDepth")), "256 levels");
    EXPECT_EQ(limitValueText(row("kLights")), "16");
    EXPECT_EQ(limitValueText({"a size", 1536.0, "bytes", "x", "y", "kNone"}), "1536 bytes");
}

TEST(LimitCatalogue, DocsContainTheGeneratedTable) {
    const std::string generated = limitCatalogueMarkdown();
    for (const Limit& limit : limitCatalogue())
        EXPECT_NE(
            generated.find("\n| " + std::string(limit.name) + " | " + limitValueText(limit) + " |"),
            std::string::npos)
            << limit.name;

    const std::string docs = readSourceFile("docs/limits.md");
    ASSERT_FALSE(docs.empty()) << "docs/limits.md is missing";
    const std::string begin = "<!-- limits:begin -->\n";
    const std::string end = "<!-- limits:end -->";
    const std::size_t from = docs.find(begin);
    const std::size_t to = docs.find(end);
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    ASSERT_LT(from, to);
    EXPECT_EQ(docs.substr(from + begin.size(), to - from - begin.size()), generated)
        << "regenerate the table in docs/limits.md with `rmsc limits --markdown`:\n"
        << generated;
}
