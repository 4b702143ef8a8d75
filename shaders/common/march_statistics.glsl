// How many fragments marched in a frame, for `rmsc bench` (engine/render/include/render/renderer.hpp,
// MarchStatistics): the fullscreen pass counts in [0], the shell pass in [1]. A fragment counts
// when its march took at least one step. The instrumented variant of the march pass
// (SDF_COUNT_EVALUATIONS) adds the primitives each pixel evaluated to the 64-bit count in [2]
// (low word) and [3] (high word: a carry whenever the low word wraps); so does the
// instrumented cone pass (passes/cone.frag), the march pass's pre-pass.
#include "generated/constants.glsl"

layout(std430, binding = MARCH_STATISTICS_BINDING) buffer MarchStatisticsBuffer {
    uint marchStatistics[4];
};

// Adds the primitives this fragment evaluated to [2] and [3] (the instrumented variant only).
void countEvaluations() {
#ifdef SDF_COUNT_EVALUATIONS
    uint before = atomicAdd(marchStatistics[2], sdfEvaluations);
    if (before + sdfEvaluations < before) atomicAdd(marchStatistics[3], 1u);
#endif
}

void countMarchedFragment(int steps, int pass) {
    if (steps > 0) atomicAdd(marchStatistics[pass], 1u);
    if (pass == 0) countEvaluations();
}
