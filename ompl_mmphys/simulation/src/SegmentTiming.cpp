#include "ompl_mmphys/simulation/SegmentTiming.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mmphys
{
    SegmentTiming::SegmentTiming(const std::vector<double> &delta, const std::vector<double> &speeds,
                                 const std::vector<double> &accelerations)
    {
        double speed = std::numeric_limits<double>::infinity();
        double acceleration = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < delta.size(); ++j)
        {
            const double distance = std::abs(delta[j]);
            if (distance == 0.0)
                continue;
            speed = std::min(speed, speeds[j] / distance);
            acceleration = std::min(acceleration, accelerations[j] / distance);
        }
        if (!std::isfinite(speed))
            return;  // nothing moves
        acceleration_ = acceleration;
        if (speed * speed / acceleration >= 1.0)
        {  // a triangle: accelerate over half the way, decelerate over the other half
            rampTime_ = std::sqrt(1.0 / acceleration);
            topSpeed_ = acceleration * rampTime_;
            duration_ = 2.0 * rampTime_;
        }
        else
        {
            rampTime_ = speed / acceleration;
            topSpeed_ = speed;
            duration_ = 1.0 / speed + rampTime_;
        }
    }

    double SegmentTiming::fraction(double t) const
    {
        if (t <= 0.0 || duration_ == 0.0)
            return duration_ == 0.0 ? 1.0 : 0.0;
        if (t >= duration_)
            return 1.0;
        const double ramp = 0.5 * acceleration_ * rampTime_ * rampTime_;
        if (t < rampTime_)
            return 0.5 * acceleration_ * t * t;
        const double decelerationStart = duration_ - rampTime_;
        if (t <= decelerationStart)
            return ramp + topSpeed_ * (t - rampTime_);
        const double left = duration_ - t;
        return 1.0 - 0.5 * acceleration_ * left * left;
    }
}  // namespace ompl_mmphys
