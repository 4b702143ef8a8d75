// The modifier catalogue's own consistency: rows in SdfModifierType order, each parameter read
// into a member of the type its ParamType says, every row of a stage with the functions that
// stage needs, and instruction kinds numbered 0, 1, ... within each stage.
#include "sdf/modifiers.hpp"

#include <gtest/gtest.h>

#include <set>
#include <type_traits>

using namespace rmsc;

namespace {

// The ParamTypes a member of type T can hold.
template <typename T> std::set<ParamType> typesFor() {
    if constexpr (std::is_same_v<T, float>) return {ParamType::Number};
    if constexpr (std::is_same_v<T, int>) return {ParamType::Integer, ParamType::Axis};
    if constexpr (std::is_same_v<T, glm::vec3>) return {ParamType::Vec3};
    if constexpr (std::is_same_v<T, glm::ivec3>) return {ParamType::IVec3};
    if constexpr (std::is_same_v<T, bool>) return {ParamType::Bool};
    if constexpr (std::is_same_v<T, glm::bvec3>) return {ParamType::Axes};
    return {};
}

} // namespace

TEST(ModifierCatalogue, RowsAreInTypeOrderWithUniqueNames) {
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < modifierCatalogue().size(); ++i) {
        const ModifierSpec& spec = modifierCatalogue()[i];
        EXPECT_EQ(std::size_t(spec.type), i) << spec.name;
        EXPECT_EQ(&modifierSpec(spec.type), &spec);
        EXPECT_EQ(findModifier(spec.name), &spec);
        EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
        EXPECT_FALSE(spec.description.empty()) << spec.name;
        EXPECT_FALSE(spec.source.empty()) << spec.name;
    }
    EXPECT_EQ(findModifier("twirl"), nullptr);
}

TEST(ModifierCatalogue, ParametersMatchTheMembersTheyAreReadInto) {
    for (const ModifierSpec& spec : modifierCatalogue()) {
        std::set<std::string_view> keys;
        for (const ModifierParam& param : spec.params) {
            EXPECT_TRUE(keys.insert(param.spec.key).second) << spec.name << "." << param.spec.key;
            EXPECT_NE(param.spec.key, "type") << spec.name;
            EXPECT_FALSE(param.spec.description.empty()) << spec.name << "." << param.spec.key;
            std::visit(
                [&](auto field) {
                    using T = std::decay_t<decltype(SdfModifier{}.*field)>;
                    EXPECT_TRUE(typesFor<T>().count(param.spec.type))
                        << spec.name << "." << param.spec.key;
                },
                param.field);
        }
    }
}

TEST(ModifierCatalogue, EachStageHasTheFunctionsItNeeds) {
    for (const ModifierSpec& spec : modifierCatalogue()) {
        EXPECT_TRUE(spec.pack) << spec.name;
        if (spec.stage == ModifierStage::Point) {
            EXPECT_TRUE(spec.movePoint && spec.preimage) << spec.name;
            EXPECT_FALSE(spec.changeDistance || spec.growth || spec.gradientGain || spec.readsPoint)
                << spec.name;
        } else {
            EXPECT_TRUE(spec.changeDistance && spec.growth) << spec.name;
            EXPECT_FALSE(spec.movePoint || spec.preimage || spec.lipschitz || spec.cells)
                << spec.name;
        }
    }
}

TEST(ModifierCatalogue, KindsNumberEachStageFromZero) {
    std::set<std::uint32_t> kinds[2];
    for (const ModifierSpec& spec : modifierCatalogue()) {
        const std::uint32_t kind = modifierKind(spec.type);
        EXPECT_TRUE(kinds[std::size_t(spec.stage)].insert(kind).second) << spec.name;
        EXPECT_EQ(&modifierOfKind(spec.stage, kind), &spec);
    }
    for (const std::set<std::uint32_t>& stage : kinds) {
        ASSERT_FALSE(stage.empty());
        EXPECT_EQ(*stage.rbegin(), std::uint32_t(stage.size() - 1));
    }
    EXPECT_EQ(modifierKind(SdfModifierType::Repeat), 0u);
    EXPECT_EQ(modifierKind(SdfModifierType::Round), 0u);
    EXPECT_EQ(modifierKind(SdfModifierType::Displace), 2u);
}

TEST(ModifierCatalogue, DefaultModifierTakesTheRowDefaults) {
    const SdfModifier twist = defaultModifier(SdfModifierType::Twist);
    EXPECT_EQ(twist.type, SdfModifierType::Twist);
    EXPECT_EQ(twist.radius, 1.0f);
    EXPECT_EQ(defaultModifier(SdfModifierType::Polar).axis, 1);
    EXPECT_EQ(defaultModifier(SdfModifierType::Displace).frequency, 1.0f);
    EXPECT_EQ(defaultModifier(SdfModifierType::Repeat).counts, glm::ivec3(0));
}
