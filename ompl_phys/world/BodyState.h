#pragma once

#include <Eigen/Geometry>

#include <vector>

namespace ompl_phys
{
    /** The dynamic state of one rigid body as the planner sees it: pose and velocities, all in the
        world frame. The moving bodies of a scene are numbered robot first (0), then the free and
        constraint-oriented bodies in scene order; PhysicsWorld and PhysicsStateSpace use the same
        numbering. */
    struct BodyState
    {
        Eigen::Vector3d position{Eigen::Vector3d::Zero()};               ///< centre, m
        Eigen::Quaterniond orientation{Eigen::Quaterniond::Identity()};  ///< body to world
        Eigen::Vector3d linearVelocity{Eigen::Vector3d::Zero()};         ///< m/s, world frame
        Eigen::Vector3d angularVelocity{Eigen::Vector3d::Zero()};        ///< rad/s, world frame

        /** True when every number is finite. */
        bool isFinite() const
        {
            return position.allFinite() && orientation.coeffs().allFinite() && linearVelocity.allFinite() &&
                   angularVelocity.allFinite();
        }
    };

    /** One BodyState per moving body, robot first, then the movable bodies in scene order. */
    using BodyStates = std::vector<BodyState>;
}  // namespace ompl_phys
