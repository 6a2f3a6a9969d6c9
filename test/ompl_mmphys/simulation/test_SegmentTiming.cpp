#include "ompl_mmphys/simulation/SegmentTiming.h"

#include <gtest/gtest.h>

#include <cmath>

using ompl_mmphys::SegmentTiming;

namespace
{
    /** The largest speed and acceleration of the fraction, from differences at step h. */
    std::pair<double, double> peakRates(const SegmentTiming &timing, double h)
    {
        double speed = 0.0, acceleration = 0.0;
        for (double t = 0.0; t + 2.0 * h <= timing.duration() + 1e-12; t += h)
        {
            const double a = timing.fraction(t), b = timing.fraction(t + h), c = timing.fraction(t + 2.0 * h);
            speed = std::max(speed, (b - a) / h);
            acceleration = std::max(acceleration, std::abs(c - 2.0 * b + a) / (h * h));
        }
        return {speed, acceleration};
    }
}  // namespace

TEST(SegmentTiming, ASegmentWithoutMotionTakesNoTime)
{
    const SegmentTiming timing({0.0, 0.0}, {1.0, 1.0}, {1.0, 1.0});
    EXPECT_EQ(timing.duration(), 0.0);
    EXPECT_EQ(timing.fraction(0.0), 1.0);
}

TEST(SegmentTiming, ALongSegmentRampsCruisesAndRampsDown)
{
    // 1 m at 0.5 m/s, 1 m/s²: half a second up to speed, 1.5 s cruising, half a second down
    const SegmentTiming timing({1.0}, {0.5}, {1.0});
    EXPECT_NEAR(timing.duration(), 2.5, 1e-12);
    EXPECT_EQ(timing.fraction(-1.0), 0.0);
    EXPECT_NEAR(timing.fraction(0.5), 0.125, 1e-12);
    EXPECT_NEAR(timing.fraction(1.25), 0.5, 1e-12);
    EXPECT_NEAR(timing.fraction(2.0), 0.875, 1e-12);
    EXPECT_EQ(timing.fraction(2.5), 1.0);
    const auto [speed, acceleration] = peakRates(timing, 1e-3);
    EXPECT_NEAR(speed, 0.5, 1e-3);
    EXPECT_LE(acceleration, 1.0 + 1e-6);
}

TEST(SegmentTiming, AShortSegmentIsATriangle)
{
    // 0.1 m never reaches 0.5 m/s at 1 m/s²: accelerate over 0.05 m, decelerate over 0.05 m
    const SegmentTiming timing({-0.1}, {0.5}, {1.0});
    EXPECT_NEAR(timing.duration(), 2.0 * std::sqrt(0.1), 1e-12);
    EXPECT_NEAR(timing.fraction(std::sqrt(0.1)), 0.5, 1e-12);
    const auto [speed, acceleration] = peakRates(timing, 1e-4);
    EXPECT_LT(speed * 0.1, 0.5);
    EXPECT_LE(acceleration * 0.1, 1.0 + 1e-6);
}

TEST(SegmentTiming, TheSlowestJointSetsThePace)
{
    // joint 1 moves twice as far at the same limits: it alone decides
    const SegmentTiming both({1.0, 2.0}, {1.0, 1.0}, {10.0, 10.0});
    const SegmentTiming second({2.0}, {1.0}, {10.0});
    EXPECT_NEAR(both.duration(), second.duration(), 1e-12);
    // a joint with a lower speed limit slows the segment down
    const SegmentTiming limited({1.0, 2.0}, {0.1, 1.0}, {10.0, 10.0});
    EXPECT_GT(limited.duration(), 9.0);
}
