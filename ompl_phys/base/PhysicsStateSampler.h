/* Samples physically sensible states of a physics scene: every body upright on the floor and at
   rest, except the robot, whose position and horizontal velocity are uniform within its limits.
   Free bodies get a uniform position and heading in the body region; constraint-oriented bodies
   a uniform position along their push axis (the only places the knowledge lets them reach). */
#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/base/StateSampler.h>

namespace ompl_phys
{
    class PhysicsStateSampler : public ompl::base::StateSampler
    {
    public:
        explicit PhysicsStateSampler(const PhysicsStateSpace *space);

        void sampleUniform(ompl::base::State *state) override;

        /** Copies near and moves the robot uniformly within distance along x and y (clamped to its region).
         */
        void sampleUniformNear(ompl::base::State *state, const ompl::base::State *near,
                               double distance) override;

        /** Copies mean and moves the robot by a normal offset of standard deviation stdDev along x and y. */
        void sampleGaussian(ompl::base::State *state, const ompl::base::State *mean, double stdDev) override;

    private:
        void moveRobot(ompl::base::State *state, const Eigen::Vector2d &offset);

        const PhysicsStateSpace &physics_;
        std::vector<std::size_t> movable_;
        BodyStates scratch_;
    };
}  // namespace ompl_phys
