// The names the panels give a group's operations (the hierarchy's "[smooth union] name", the Add
// menus, the inspector's operation list), in the order they are offered.
#pragma once

#include "sdf/sdf_tree.hpp"

namespace rmsc::app {

struct OpName {
    SdfOp op;
    const char* label;
};
constexpr OpName kOps[] = {
    {SdfOp::Union, "union"},
    {SdfOp::Subtraction, "subtraction"},
    {SdfOp::Intersection, "intersection"},
    {SdfOp::SmoothUnion, "smooth union"},
    {SdfOp::SmoothSubtraction, "smooth subtraction"},
    {SdfOp::SmoothIntersection, "smooth intersection"},
};

const char* opLabel(SdfOp op); // "?" for one not in kOps
bool isSmooth(SdfOp op);       // blends with the group's smoothness

} // namespace rmsc::app
