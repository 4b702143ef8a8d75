// The operation catalogue: one row per SdfOp (its JSON name, how it combines the children, the
// kind of seam it leaves and what it does). The scene reader, the writer, the schema, the docs
// table, the compiler's checks and messages and the bounds read this table; the op's number is
// the Combine instruction's kind, and the GLSL names of those numbers are generated from it
// (sdf/glsl_constants.hpp). Formulas: sdfCombine in shaders/common/sdf_functions.glsl and in
// engine/sdf/sdf_functions.cpp (sdf/sdf_functions.hpp).
#pragma once

#include "sdf/param_spec.hpp"
#include "sdf/sdf_tree.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc {

// What the children make together (operations fold left to right: ((a op b) op c)).
enum class SdfOpCombination {
    Union,        // inside any child
    Subtraction,  // inside the first child and outside the later ones
    Intersection, // inside every child
    Xor,          // inside exactly one of two (folded)
};

// The seam where the children meet.
enum class SdfOpSeam {
    Hard,    // the plain min / max
    Smooth,  // a smooth minimum `smoothness` wide, its curve chosen by `blend`
    Chamfer, // a 45-degree chamfer of size `smoothness`
    Round,   // a quarter circle of radius `smoothness`
};

struct OperationSpec {
    SdfOp op;
    std::string_view name; // JSON value of "op"
    SdfOpCombination combination;
    SdfOpSeam seam;
    std::string_view description; // for the docs
};

// The curves of the smooth operations' seam ("blend").
struct BlendSpec {
    SmoothBlend blend;
    std::string_view name; // JSON value of "blend"
    std::string_view description;
};

std::span<const OperationSpec> operationCatalogue();
const OperationSpec& operationSpec(SdfOp op);
const OperationSpec* findOperation(std::string_view name); // nullptr if unknown
std::vector<std::string> operationNames();                 // JSON names, in catalogue order

std::span<const BlendSpec> blendCatalogue(); // in SmoothBlend order, the default first
std::vector<std::string> blendNames();

// The seam needs "smoothness" (> 0): the smooth, chamfer and round operations.
bool takesSmoothness(SdfOp op);
// The key "smoothness" of those groups: its range, for the reader, the schema and the inspector.
const SdfParamSpec& smoothnessParam();
// "blend" chooses the seam's curve: the smooth operations.
bool takesBlend(SdfOp op);
// The name for messages: "smooth union".
std::string operationLabel(SdfOp op);
// Lower bounds of the form f(y) >= distance(y, box) - drop, for every y outside the box (the
// per-cell pruning skips a subtree whose bound already decides the operation, sdf/
// cell_pruning.hpp): given such bounds for the operands, which box bounds the operation and
// how much further it may fall. Derived from the row's combination and seam: a union-like one
// is bounded by the box around both operands, its seam dipping below their minimum (a smooth
// minimum by its curve's dip; a chamfer or round union by up to sqrt 2 times the operands'
// drop plus a share of k where an operand is below zero); a subtraction is at least its first
// operand, an intersection at least either, xor at least their minimum.
enum class SdfFloorBox { BothOperands, FirstOperand, EitherOperand };
struct SdfOperationFloor {
    SdfFloorBox box = SdfFloorBox::BothOperands;
    float dropScale = 1.0f;      // the operands' largest drop times this...
    float smoothnessDrop = 0.0f; // ...plus smoothness k times this
};
SdfOperationFloor operationFloor(SdfOp op, SmoothBlend blend);

// The operation of `op`'s seam that makes `combination` (a plain one for xor):
// cut children are subtracted with withCombination(op, Subtraction).
SdfOp withCombination(SdfOp op, SdfOpCombination combination);

} // namespace rmsc
