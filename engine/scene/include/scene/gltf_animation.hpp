// glTF animations as plain data, and the value of one sampler at a time (glTF 2.0 section 3.11,
// "Animations", and Appendix C, "Animation Sampler Interpolation Modes").
#pragma once

#include <string>
#include <vector>

namespace rmsc {

enum class AnimationInterpolation { Linear, Step, CubicSpline };
enum class AnimationPath { Translation, Rotation, Scale, Weights };

// One glTF animation sampler: key times and the values at them.
struct AnimationSampler {
    std::vector<float> times; // seconds, strictly increasing, at least one
    // Per key: `width` floats; for CUBICSPLINE three groups of `width` per key, in-tangent,
    // value and out-tangent, as the file stores them.
    std::vector<float> values;
    int width = 0; // floats of one value: 3, 4 (a rotation, x y z w) or the morph target count
    AnimationInterpolation interpolation = AnimationInterpolation::Linear;
};

// One channel: which sampler drives which property of which node.
struct AnimationChannel {
    int sampler = 0; // index into Animation::samplers
    int node = 0;    // index into the file's nodes
    AnimationPath path = AnimationPath::Translation;
};

struct Animation {
    std::string name; // "" when the file gives none
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    float duration = 0.0f; // the last key time of all its samplers (>= 0)
};

// Writes the value of `sampler` at `time` to out[0 .. width). Before the first key it is the
// first key's value, after the last key the last's. `rotation`: the values are unit quaternions,
// interpolated by slerp along the shorter arc for LINEAR and normalised for CUBICSPLINE.
void sampleAnimation(const AnimationSampler& sampler, double time, bool rotation, float* out);

} // namespace rmsc
