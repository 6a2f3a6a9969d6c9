#include "ompl_phys/control/SpeedGovernor.h"

#include <algorithm>

namespace ompl_phys
{
    SpeedGovernor::SpeedGovernor(const PhysicsScene &scene)
        : mass_(scene.robot.mass),
          speed_(SPEED_MARGIN * scene.limits.maxRobotSpeed),
          maxForce_(scene.limits.maxForce)
    {
    }

    Eigen::Vector2d SpeedGovernor::force(const Eigen::Vector2d &commanded, const Eigen::Vector2d &velocity,
                                         double dt) const
    {
        const Eigen::Vector2d next = velocity + commanded * (dt / mass_);
        const double speed = next.norm();
        if (speed <= speed_)
            return commanded;
        const Eigen::Vector2d bounded = (next * (speed_ / speed) - velocity) * (mass_ / dt);
        return bounded.cwiseMax(-maxForce_).cwiseMin(maxForce_);
    }
}  // namespace ompl_phys
