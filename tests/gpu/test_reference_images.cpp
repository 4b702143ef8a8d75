// Reference images of the sample scenes: each rendered at 256x144 and compared with
// tests/reference/<scene>.png. Tolerance: a pixel differs when a channel is off by more than
// 8 of 255; at most 0.5% of pixels may differ. A failure writes the actual and a diff image to
// <build>/test-output/; with RMSC_UPDATE_REFERENCES=1 also <scene>.candidate.png, and the test
// still fails. Review a candidate, then commit it with tools/promote-references.sh -m "what
// changed in the picture and why" <scene>; nothing else writes tests/reference/.
#include "gpu_test_support.hpp"

using namespace rmsc;
using namespace rmsc::test;

class ReferenceImage : public ::testing::TestWithParam<const char*> {};

TEST_P(ReferenceImage, MatchesWithinTolerance) {
    const std::string name = GetParam();
    const PreparedScene prepared = openRepositoryScene("samples/scenes/" + name + ".json");
    const FrameTargets targets = renderPrepared(prepared, 256, 144);
    EXPECT_TRUE(imageMatchesReference(readDisplayColor(targets), name));
}

INSTANTIATE_TEST_SUITE_P(Samples, ReferenceImage,
                         ::testing::Values("demo", "shapes", "csg", "mesh_cut", "gltf_instances",
                                           "modifiers", "pawn", "chessboard", "materials",
                                           "primitives", "fractals", "smooth_blend", "shells"),
                         [](const auto& param) { return std::string(param.param); });
