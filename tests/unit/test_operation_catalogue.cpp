// The operation catalogue: rows in SdfOp order with unique names, which operations take
// "smoothness" and "blend", and the subtraction each one's cut children are subtracted with.
#include "sdf/operations.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace rmsc;

TEST(OperationCatalogue, RowsAreInOpOrderWithUniqueNames) {
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < operationCatalogue().size(); ++i) {
        const OperationSpec& spec = operationCatalogue()[i];
        EXPECT_EQ(std::size_t(spec.op), i) << spec.name;
        EXPECT_EQ(findOperation(spec.name), &spec);
        EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
        EXPECT_FALSE(spec.description.empty()) << spec.name;
    }
    EXPECT_EQ(operationCatalogue().size(), std::size_t(SdfOp::RoundIntersection) + 1);
    EXPECT_EQ(findOperation("smooth"), nullptr);
}

TEST(OperationCatalogue, SmoothnessAndBlendFollowTheSeam) {
    EXPECT_FALSE(takesSmoothness(SdfOp::Union));
    EXPECT_FALSE(takesSmoothness(SdfOp::Xor));
    EXPECT_TRUE(takesSmoothness(SdfOp::SmoothSubtraction));
    EXPECT_TRUE(takesSmoothness(SdfOp::ChamferUnion));
    EXPECT_TRUE(takesSmoothness(SdfOp::RoundIntersection));
    EXPECT_TRUE(takesBlend(SdfOp::SmoothUnion));
    EXPECT_FALSE(takesBlend(SdfOp::ChamferUnion));
    EXPECT_FALSE(takesBlend(SdfOp::Intersection));
    EXPECT_EQ(operationLabel(SdfOp::ChamferIntersection), "chamfer intersection");
}

TEST(OperationCatalogue, CutChildrenAreSubtractedWithTheGroupsSeam) {
    const auto cut = [](SdfOp op) { return withCombination(op, SdfOpCombination::Subtraction); };
    EXPECT_EQ(cut(SdfOp::Union), SdfOp::Subtraction);
    EXPECT_EQ(cut(SdfOp::Xor), SdfOp::Subtraction);
    EXPECT_EQ(cut(SdfOp::SmoothIntersection), SdfOp::SmoothSubtraction);
    EXPECT_EQ(cut(SdfOp::ChamferUnion), SdfOp::ChamferSubtraction);
    EXPECT_EQ(cut(SdfOp::RoundSubtraction), SdfOp::RoundSubtraction);
    EXPECT_EQ(withCombination(SdfOp::RoundSubtraction, SdfOpCombination::Union), SdfOp::RoundUnion);
}

TEST(OperationCatalogue, BlendsAreInSmoothBlendOrderWithTheDefaultFirst) {
    ASSERT_EQ(blendCatalogue().size(), 2u);
    EXPECT_EQ(blendCatalogue()[0].blend, SmoothBlend::Polynomial);
    EXPECT_EQ(blendCatalogue()[0].blend, SdfNode{}.blend);
    EXPECT_EQ(blendCatalogue()[1].blend, SmoothBlend::Circular);
    EXPECT_EQ(blendNames(), (std::vector<std::string>{"polynomial", "circular"}));
}
