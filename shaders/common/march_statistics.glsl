// How many fragments marched in a frame, for `rmsc bench` (engine/render/renderer.hpp,
// MarchStatistics): the fullscreen pass counts in [0], the shell pass in [1]. A fragment counts
// when its march took at least one step. The instrumented variant of the march pass
// (SDF_COUNT_EVALUATIONS) adds the primitives each pixel evaluated to the 64-bit count in [2]
// (low word) and [3] (high word: a carry whenever the low word wraps).
layout(std430, binding = 5) buffer MarchStatisticsBuffer { // kMarchStatisticsBinding
    uint marchStatistics[4];
};

void countMarchedFragment(int steps, int pass) {
    if (steps > 0) atomicAdd(marchStatistics[pass], 1u);
#ifdef SDF_COUNT_EVALUATIONS
    if (pass == 0) {
        uint before = atomicAdd(marchStatistics[2], sdfEvaluations);
        if (before + sdfEvaluations < before) atomicAdd(marchStatistics[3], 1u);
    }
#endif
}
