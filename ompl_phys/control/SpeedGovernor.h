#pragma once

#include "ompl_phys/scene/PhysicsScene.h"

#include <Eigen/Core>

namespace ompl_phys
{
    /** The robot's drive as a controller that keeps the speed limit: the force of a control is
        applied as given while the robot's horizontal speed after the next ODE step stays below
        SPEED_MARGIN × max_robot_speed; otherwise it is the force that brings the speed to that
        bound (the part of the control that would speed the robot up further is not applied),
        each component within max_force. So a control held for long cruises at the limit instead
        of breaking it, and propagations are no longer cut short by it. The prediction is a free
        sphere's (v + F dt / m): floor friction and pushes slow the robot, which only keeps it
        further below the limit. Deterministic, so replays stay exact. */
    class SpeedGovernor
    {
    public:
        /** The share of max_robot_speed the governor holds the robot to: the limit itself is still
            checked, and rounding or a contact must not lift the speed over it. */
        static constexpr double SPEED_MARGIN = 0.99;

        /** A governor for the scene's robot and limits. */
        explicit SpeedGovernor(const PhysicsScene &scene);

        /** The force to apply for the next ODE step of dt seconds, N, given the commanded force and
            the robot's horizontal velocity now, m/s. */
        Eigen::Vector2d force(const Eigen::Vector2d &commanded, const Eigen::Vector2d &velocity,
                              double dt) const;

    private:
        double mass_;
        double speed_;
        double maxForce_;
    };
}  // namespace ompl_phys
