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
// The operation of `op`'s seam that makes `combination` (a plain one for xor):
// cut children are subtracted with withCombination(op, Subtraction).
SdfOp withCombination(SdfOp op, SdfOpCombination combination);

} // namespace rmsc
