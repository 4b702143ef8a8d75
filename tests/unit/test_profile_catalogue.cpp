// The profile catalogue: rows in SdfProfileType and SdfProfileSolid order with unique names,
// each parameter read into a member of the type its ParamType says, and the rows' checks.
#include "sdf/profiles.hpp"

#include <gtest/gtest.h>

#include <set>
#include <type_traits>

using namespace rmsc;

namespace {

template <typename T> ParamType typeFor() {
    if constexpr (std::is_same_v<T, float>) return ParamType::Number;
    if constexpr (std::is_same_v<T, glm::vec2>) return ParamType::Vec2;
    return ParamType::Points;
}

void expectMatchingField(const ProfileParam& param) {
    std::visit(
        [&](auto field) {
            using T = std::decay_t<decltype(SdfProfile{}.*field)>;
            EXPECT_EQ(typeFor<T>(), param.spec.type) << param.spec.key;
        },
        param.field);
}

} // namespace

TEST(ProfileCatalogue, RowsAreInEnumOrderWithUniqueNames) {
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < profileCatalogue().size(); ++i) {
        const ProfileSpec& spec = profileCatalogue()[i];
        EXPECT_EQ(std::size_t(spec.type), i) << spec.name;
        EXPECT_EQ(findProfile(spec.name), &spec);
        EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
        for (const ProfileParam& param : spec.params)
            expectMatchingField(param);
    }
    EXPECT_EQ(profileCatalogue().size(), std::size_t(SdfProfileType::Polygon) + 1);
    for (std::size_t i = 0; i < profileSolidCatalogue().size(); ++i) {
        const ProfileSolidSpec& solid = profileSolidCatalogue()[i];
        EXPECT_EQ(std::size_t(solid.solid), i) << solid.name;
        EXPECT_EQ(findProfileSolid(solid.name), &solid);
        expectMatchingField(solid.param);
    }
    EXPECT_EQ(findProfileSolid("sphere"), nullptr);
}

TEST(ProfileCatalogue, ChecksReportOnlyWhatTheirParametersAllow) {
    const ProfileSpec& rounded = profileSpec(SdfProfileType::RoundedRectangle);
    SdfProfile profile;
    profile.halfSize = {0.2f, 0.1f};
    profile.radius = 0.15f;
    std::vector<ParamProblem> problems;
    rounded.check(profile, 3u, problems);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].key, "radius");
    EXPECT_EQ(problems[0].message,
              "the corner radius 0.15 is larger than the smaller half size 0.1");
    problems.clear();
    rounded.check(profile, 2u, problems); // half_size unreadable: nothing to compare with
    EXPECT_TRUE(problems.empty());

    SdfProfile line;
    line.points = {{0, 0}, {1, 1}, {2, 2}};
    profileSpec(SdfProfileType::Polygon).check(line, 1u, problems);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].key, "points");
}
