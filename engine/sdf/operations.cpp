// The operation catalogue rows (sdf/operations.hpp).
#include "sdf/operations.hpp"

#include <algorithm>
#include <cassert>
#include <limits>

namespace rmsc {
namespace {

using C = SdfOpCombination;
using S = SdfOpSeam;

// In SdfOp order.
const OperationSpec kCatalogue[] = {
    {SdfOp::Union, "union", C::Union, S::Hard, "Everything inside any child."},
    {SdfOp::Subtraction, "subtraction", C::Subtraction, S::Hard,
     "The first child minus all later children (needs at least two children)."},
    {SdfOp::Intersection, "intersection", C::Intersection, S::Hard, "What is inside every child."},
    {SdfOp::SmoothUnion, "smooth_union", C::Union, S::Smooth,
     "Union with the seams blended over about `smoothness` metres (smooth minimum, curve chosen "
     "by `blend`). Materials blend with the same factor as the distances, so a red and a blue "
     "child show a gradient across the seam."},
    {SdfOp::SmoothSubtraction, "smooth_subtraction", C::Subtraction, S::Smooth,
     "Subtraction with blended cut edges; the cut surface keeps the first child's material."},
    {SdfOp::SmoothIntersection, "smooth_intersection", C::Intersection, S::Smooth,
     "Intersection with blended edges; materials blend as for `smooth_union`."},
    {SdfOp::Xor, "xor", C::Xor, S::Hard,
     "What is inside exactly one child (folded left to right: inside an odd number of "
     "children)."},
    {SdfOp::ChamferUnion, "chamfer_union", C::Union, S::Chamfer,
     "Union with a 45-degree bevel in the inside corners of the seam, meeting each child "
     "`smoothness` metres from the seam."},
    {SdfOp::ChamferSubtraction, "chamfer_subtraction", C::Subtraction, S::Chamfer,
     "Subtraction with the cut edges bevelled."},
    {SdfOp::ChamferIntersection, "chamfer_intersection", C::Intersection, S::Chamfer,
     "Intersection with the edges bevelled."},
    {SdfOp::RoundUnion, "round_union", C::Union, S::Round,
     "Union with the inside corners of the seam filled by a quarter circle of radius "
     "`smoothness`."},
    {SdfOp::RoundSubtraction, "round_subtraction", C::Subtraction, S::Round,
     "Subtraction with the cut edges rounded to radius `smoothness`."},
    {SdfOp::RoundIntersection, "round_intersection", C::Intersection, S::Round,
     "Intersection with the edges rounded to radius `smoothness`."},
};

// In SmoothBlend order. Quilez, "Smooth minimum" (https://iquilezles.org/articles/smin/).
const BlendSpec kBlends[] = {
    {SmoothBlend::Polynomial, "polynomial",
     "a quadratic polynomial: the seam dips by `k`/4 where both children are equally near"},
    {SmoothBlend::Circular, "circular", "a circular arc: dips by `k`(1 - 1/√2), rounder"},
};

constexpr SdfParamSpec kSmoothness = {
    .key = "smoothness",
    .type = ParamType::Number,
    .required = true,
    // At least a millimetre: the seam's formulas divide by it, and a tiny float
    // (1e-38) overflows them on the GPU.
    .range = closedRange(1e-3, std::numeric_limits<double>::infinity(), Unit::Metres),
    .description = "the width of the seam, in world units: the smooth minimum's `k`, the "
                   "chamfer's size, the rounding radius"};

} // namespace

std::span<const OperationSpec> operationCatalogue() {
    return kCatalogue;
}

const OperationSpec& operationSpec(SdfOp op) {
    assert(std::size_t(op) < std::size(kCatalogue) && kCatalogue[std::size_t(op)].op == op);
    return kCatalogue[std::size_t(op)];
}

const OperationSpec* findOperation(std::string_view name) {
    for (const OperationSpec& spec : kCatalogue)
        if (spec.name == name) return &spec;
    return nullptr;
}

std::vector<std::string> operationNames() {
    std::vector<std::string> names;
    for (const OperationSpec& spec : kCatalogue)
        names.emplace_back(spec.name);
    return names;
}

std::span<const BlendSpec> blendCatalogue() {
    return kBlends;
}

std::vector<std::string> blendNames() {
    std::vector<std::string> names;
    for (const BlendSpec& spec : kBlends)
        names.emplace_back(spec.name);
    return names;
}

bool takesSmoothness(SdfOp op) {
    return operationSpec(op).seam != SdfOpSeam::Hard;
}

const SdfParamSpec& smoothnessParam() {
    return kSmoothness;
}

bool takesBlend(SdfOp op) {
    return operationSpec(op).seam == SdfOpSeam::Smooth;
}

std::string operationLabel(SdfOp op) {
    std::string label(operationSpec(op).name);
    std::replace(label.begin(), label.end(), '_', ' ');
    return label;
}

SdfOp withCombination(SdfOp op, SdfOpCombination combination) {
    const SdfOpSeam seam = operationSpec(op).seam;
    for (const OperationSpec& spec : kCatalogue)
        if (spec.combination == combination && spec.seam == seam) return spec.op;
    for (const OperationSpec& spec : kCatalogue)
        if (spec.combination == combination && spec.seam == SdfOpSeam::Hard) return spec.op;
    assert(false && "every combination has a hard operation");
    return op;
}

SdfOperationFloor operationFloor(SdfOp op, SmoothBlend blend) {
    const OperationSpec& spec = operationSpec(op);
    switch (spec.combination) {
    case SdfOpCombination::Subtraction: // max(a, -b) and its seams are never below a
        return {SdfFloorBox::FirstOperand};
    case SdfOpCombination::Intersection: // max(a, b) and its seams are never below either
        return {SdfFloorBox::EitherOperand};
    case SdfOpCombination::Xor: // max(min(a, b), -max(a, b)) >= min(a, b)
        return {SdfFloorBox::BothOperands};
    case SdfOpCombination::Union:
        break;
    }
    constexpr float kSqrt2 = 1.41421356f;
    switch (spec.seam) {
    case SdfOpSeam::Hard:
        return {SdfFloorBox::BothOperands};
    case SdfOpSeam::Smooth: // Quilez's smooth minimum dips k/4 (polynomial), k(1 - 1/sqrt 2)
        return {SdfFloorBox::BothOperands, 1.0f,
                blend == SmoothBlend::Circular ? 1.0f - 1.0f / kSqrt2 : 0.25f};
    case SdfOpSeam::Chamfer: // (a + b - k) / sqrt 2 with a, b >= m: sqrt 2 m - k / sqrt 2
        return {SdfFloorBox::BothOperands, kSqrt2, 1.0f / kSqrt2};
    case SdfOpSeam::Round: // k - |(k - a, k - b)| with a, b >= m: sqrt 2 m - (sqrt 2 - 1) k
        return {SdfFloorBox::BothOperands, kSqrt2, kSqrt2 - 1.0f};
    }
    return {SdfFloorBox::BothOperands};
}

} // namespace rmsc
