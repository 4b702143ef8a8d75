// How many fragments marched in a frame, for `rmsc bench` (engine/render/renderer.hpp,
// MarchStatistics): the fullscreen pass counts in [0], the shell pass in [1]. A fragment counts
// when its march took at least one step.
layout(std430, binding = 5) buffer MarchStatisticsBuffer { // kMarchStatisticsBinding
    uint marchedFragments[2];
};

void countMarchedFragment(int steps, int pass) {
    if (steps > 0) atomicAdd(marchedFragments[pass], 1u);
}
