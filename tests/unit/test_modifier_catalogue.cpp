// The modifier catalogue's own consistency: rows in SdfModifierType order, each parameter read
// into a member of the type its ParamType says, every row of a stage with the functions that
// stage needs, instruction kinds numbered 0, 1, ... within each stage, and each row's formula
// the one of sdf/sdf_functions.hpp for its kind.
#include "sdf/modifiers.hpp"

#include "sdf/sdf_functions.hpp"

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

// The kinds of sdf/sdf_functions.hpp are the rows' instruction kinds, and each row's formula
// is the one of its kind (the parity test compares those with the GLSL).
TEST(ModifierCatalogue, RowFormulasAreTheSdfFunctionsOfTheirKind) {
    EXPECT_EQ(modifierKind(SdfModifierType::Taper), std::uint32_t(SdfPointModifierKind::Taper));
    EXPECT_EQ(modifierKind(SdfModifierType::Displace),
              std::uint32_t(SdfDistanceModifierKind::Displace));
    const glm::vec3 points[] = {{0.3f, -0.7f, 1.1f}, {-2.5f, 0.4f, 0.2f}, {0.05f, 1.9f, -0.8f}};
    for (const ModifierSpec& spec : modifierCatalogue()) {
        SdfModifier m = defaultModifier(spec.type);
        if (spec.type == SdfModifierType::Repeat) m.vector = glm::vec3(1.0f, 0.0f, 2.0f);
        if (spec.type == SdfModifierType::Polar) m.count = 5;
        if (spec.type == SdfModifierType::Taper) m.amount = 0.3f;
        glm::vec4 params[3]{};
        spec.pack(m, 1.0f, -1, params);
        const std::uint32_t kind = modifierKind(spec.type);
        for (const glm::vec3& p : points) {
            if (spec.stage == ModifierStage::Point) {
                EXPECT_EQ(spec.movePoint(p, params),
                          sdfPointModifier(SdfPointModifierKind(kind), p, params))
                    << spec.name;
            } else {
                EXPECT_EQ(spec.changeDistance(0.25f, p, params),
                          sdfDistanceModifier(SdfDistanceModifierKind(kind), 0.25f, p, params[0]))
                    << spec.name;
            }
        }
    }
}

TEST(ModifierCatalogue, DefaultModifierTakesTheRowDefaults) {
    const SdfModifier twist = defaultModifier(SdfModifierType::Twist);
    EXPECT_EQ(twist.type, SdfModifierType::Twist);
    EXPECT_EQ(twist.radius, 1.0f);
    EXPECT_EQ(defaultModifier(SdfModifierType::Polar).axis, 1);
    EXPECT_EQ(defaultModifier(SdfModifierType::Displace).frequency, 1.0f);
    EXPECT_EQ(defaultModifier(SdfModifierType::Repeat).counts, glm::ivec3(0));
}
