// The operation catalogue: rows in SdfOp order with unique names, which operations take
// "smoothness" and "blend", the subtraction each one's cut children are subtracted with, and
// the lower bounds each one keeps (operationFloor).
#include "sdf/operations.hpp"
#include "sdf/sdf_functions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
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

// operationFloor: with operands at least d - drop at a point d outside their boxes, the
// operation is at least d - (dropScale * drop + smoothnessDrop * k) there (the per-cell
// pruning drops subtrees on this, sdf/cell_pruning.hpp). Checked on random operands near and
// below the bound, for every operation, both blends, with and without the operands' own drop;
// the smooth union's dip (k/4, or k(1 - 1/sqrt 2) circular) is reached, so a smaller factor
// fails.
TEST(OperationCatalogue, FloorsHoldForEveryOperation) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const OperationSpec& spec : operationCatalogue())
        for (SmoothBlend blend : {SmoothBlend::Polynomial, SmoothBlend::Circular}) {
            const SdfOperationFloor rule = operationFloor(spec.op, blend);
            float tightest = INFINITY;
            for (int n = 0; n < 20000; ++n) {
                const float k = 0.01f + 2.0f * unit(rng);
                const float d = 3.0f * unit(rng);
                const float drop = n % 2 ? 2.0f * unit(rng) : 0.0f;
                // Operands at their bound or above it (often exactly at it).
                const auto operand = [&] {
                    return d - drop + (unit(rng) < 0.3f ? 0.0f : 3.0f * unit(rng));
                };
                const auto anything = [&] { return 6.0f * unit(rng) - 3.0f; };
                float a = operand(), b = operand();
                // Either operand bounds an intersection: the other is anything.
                if (rule.box == SdfFloorBox::EitherOperand) (n % 4 < 2 ? b : a) = anything();
                if (rule.box == SdfFloorBox::FirstOperand) b = anything();
                const glm::vec4 params(k, blend == SmoothBlend::Circular ? 1.0f : 0.0f, 0, 0);
                float w = 0.0f;
                const float value = sdfCombine(spec.op, a, b, params, w);
                const float bound = d - (rule.dropScale * drop + rule.smoothnessDrop * k);
                ASSERT_GE(value, bound - 1e-4f * (1.0f + std::abs(bound)))
                    << spec.name << " a " << a << " b " << b << " k " << k << " d " << d << " drop "
                    << drop;
                if (drop == 0.0f) tightest = std::min(tightest, (value - bound) / k);
            }
            // The bound is reached (to 2% of k) where the seam dips: it is not loose either.
            if (spec.seam == SdfOpSeam::Smooth && spec.combination == SdfOpCombination::Union) {
                EXPECT_LT(tightest, 0.02f) << spec.name;
            }
        }
}
