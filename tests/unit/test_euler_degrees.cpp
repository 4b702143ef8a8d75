// The scene format's Euler angles (core/transform.hpp): x first, then y, then z about the fixed
// axes, and the short degrees that give a quaternion back exactly, or none.
#include "core/transform.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;

TEST(EulerDegrees, ShortDegreesComeBackExactlyAndOthersNot) {
    const glm::vec3 typed[] = {{0, 30, 0},  {10, 20, 30},  {-45, 0, 120},        {90, 90, 0},
                               {0, -90, 0}, {0, 0, -0.5f}, {179.5f, 12.25f, -33}};
    for (const glm::vec3& degrees : typed) {
        const glm::quat q = eulerDegreesToQuaternion(degrees);
        const std::optional<glm::vec3> back = exactEulerDegrees(q);
        ASSERT_TRUE(back) << degrees.x << " " << degrees.y << " " << degrees.z;
        EXPECT_EQ(eulerDegreesToQuaternion(*back), q) << "not exact";
        // The same rotation: equal angles, or at y = +-90 degrees another x, z pair.
        if (std::abs(degrees.y) != 90.0f) {
            EXPECT_EQ(*back, degrees) << back->x << " " << back->y << " " << back->z;
        }
    }
    // X first: a quarter turn about x, then about y, takes +y to +z and then to +x.
    const glm::quat xy = eulerDegreesToQuaternion({90, 90, 0});
    const glm::vec3 moved = xy * glm::vec3(0, 1, 0);
    EXPECT_NEAR(moved.x, 1.0f, 1e-6f);
    EXPECT_NEAR(moved.y, 0.0f, 1e-6f);
    EXPECT_NEAR(moved.z, 0.0f, 1e-6f);
    // A rotation no short degrees give: none.
    EXPECT_FALSE(exactEulerDegrees(glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f))));
    EXPECT_EQ(exactEulerDegrees(glm::quat(1, 0, 0, 0)), glm::vec3(0.0f));
}

// A rotation without short degrees (a gizmo's turn) shows its extracted angles, their float
// noise as 0: a field read "-0.0°" where nothing was turned. A small angle that is not noise
// stays.
TEST(EulerDegrees, ShownDegreesShowNoiseAsZero) {
    const glm::quat turned =
        glm::angleAxis(0.3f, glm::vec3(0, 1, 0)) * glm::angleAxis(-1e-7f, glm::vec3(1, 0, 0));
    ASSERT_FALSE(exactEulerDegrees(turned));
    const glm::vec3 raw = eulerDegrees(turned);
    ASSERT_TRUE(raw.x < 0.0f || std::signbit(raw.x) || raw.z < 0.0f || std::signbit(raw.z))
        << "the case this test is about: the extraction gives a negative x or z";
    const glm::vec3 shown = shownEulerDegrees(turned);
    EXPECT_EQ(shown.x, 0.0f);
    EXPECT_FALSE(std::signbit(shown.x));
    EXPECT_EQ(shown.z, 0.0f);
    EXPECT_FALSE(std::signbit(shown.z));
    EXPECT_NEAR(shown.y, 17.188734f, 1e-5f); // measured 2e-7 off; 5 ulp of float here
    const glm::quat small = glm::angleAxis(0.3f, glm::vec3(0, 1, 0)) *
                            glm::angleAxis(glm::radians(0.04f), glm::vec3(1, 0, 0));
    EXPECT_NEAR(shownEulerDegrees(small).x, 0.04f, 1e-6f); // measured 5e-9 off
    // Short degrees are shown as typed.
    EXPECT_EQ(shownEulerDegrees(eulerDegreesToQuaternion({0, 30, 0})), glm::vec3(0, 30, 0));
}
