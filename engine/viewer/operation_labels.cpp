// Operation names (see operation_labels.hpp).
#include "operation_labels.hpp"

namespace rmsc::app {

const char* opLabel(SdfOp op) {
    for (const OpName& o : kOps)
        if (o.op == op) return o.label;
    return "?";
}

bool isSmooth(SdfOp op) {
    return op == SdfOp::SmoothUnion || op == SdfOp::SmoothSubtraction ||
           op == SdfOp::SmoothIntersection;
}

} // namespace rmsc::app
