// Numbers as text (core/number_text.hpp): the shortest text that reads back as the same float,
// and the short decimal a float sits a few ulps off (what the scene writer gives Euler angles).
#include "core/number_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace rmsc;

TEST(NumberText, ShortestTextReadsBackAsTheSameFloat) {
    EXPECT_EQ(shortestNumberText(0.1f), "0.1");
    EXPECT_EQ(shortestNumberText(100000.0f), "100000");
    EXPECT_EQ(shortestNumberText(-0.099999994f), "-0.099999994");
    EXPECT_EQ(std::stof(shortestNumberText(1.0f / 3.0f)), 1.0f / 3.0f);
}

TEST(NumberText, NearestShortDecimalTakesTheShortOneWithinItsUlps) {
    EXPECT_EQ(nearestShortDecimal(30.000002f), 30.0f);                  // 1 ulp off
    EXPECT_EQ(nearestShortDecimal(-0.099999994f), -0.1f);               // 1 ulp off
    EXPECT_EQ(nearestShortDecimal(std::nextafter(0.25f, 1.0f)), 0.25f); // above
    // 30 is further than the ulps allowed: the nearest 7-digit decimal instead.
    const float far = 30.0f + 8.0f * (std::nextafter(30.0f, 31.0f) - 30.0f);
    EXPECT_NE(nearestShortDecimal(far, 2), 30.0f);
    EXPECT_EQ(shortestNumberText(nearestShortDecimal(far, 2)), "30.00002");
    EXPECT_EQ(nearestShortDecimal(far, 16), 30.0f);
    // At most 7 digits: 1/3 (0.33333334) is 0.3333333.
    EXPECT_EQ(shortestNumberText(nearestShortDecimal(1.0f / 3.0f)), "0.3333333");
    EXPECT_EQ(nearestShortDecimal(0.0f), 0.0f);
    EXPECT_TRUE(std::isnan(nearestShortDecimal(std::numeric_limits<float>::quiet_NaN())));
    EXPECT_EQ(nearestShortDecimal(INFINITY), INFINITY);
}
