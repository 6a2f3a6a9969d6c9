/* How long a position-controlled robot takes along one straight segment of a plan, and where it is
   on the way: a trapezoidal speed profile within every joint's speed and acceleration limits. */
#pragma once

#include <vector>

namespace ompl_mmphys
{
    /** Motion along a segment from joint values a to b as a fraction s(t) in [0, 1] of the way, the
        joints moving together in a straight line: from rest, at constant acceleration up to the
        cruise speed, then decelerating to rest at b (a triangle when the segment is too short to
        reach the cruise speed). The fraction's speed and acceleration are the largest that keep
        every joint within its limits. */
    class SegmentTiming
    {
    public:
        /** The timing of the segment whose joints move by delta (b - a), with each joint's speed and
            acceleration limits (same size as delta, all > 0). A segment without motion takes no time. */
        SegmentTiming(const std::vector<double> &delta, const std::vector<double> &speeds,
                      const std::vector<double> &accelerations);

        /** How long the segment takes, seconds (0 without motion). */
        double duration() const { return duration_; }
        /** The fraction of the way covered at time t (0 before, 1 from duration() on). */
        double fraction(double t) const;

    private:
        double acceleration_{0.0};  ///< of the fraction, 1/s²
        double rampTime_{0.0};      ///< time to reach the top speed, s
        double topSpeed_{0.0};      ///< the cruise speed, or the triangle's peak, 1/s
        double duration_{0.0};
    };
}  // namespace ompl_mmphys
