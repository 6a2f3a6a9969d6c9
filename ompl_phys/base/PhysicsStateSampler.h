#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/base/StateSampler.h>

namespace ompl_phys
{
    /** Samples states of a physics scene for the planners to grow towards: the robot at a uniform
        position and horizontal velocity within its limits, every movable body at rest at its start
        pose. Bodies move only when pushed, so targets that leave them in place make the nearest
        tree state the one closest in robot position among those that disturbed the scene least;
        uniform body poses would drown the robot's position in the distance (four bodies outweigh
        the robot) and slowed RRT and SyCLoP-RRT several-fold. Goal samples (PhysicsGoal) move
        bodies that occupy the goal out of the way. Like any OMPL sampler, one per thread. */
    class PhysicsStateSampler : public ompl::base::StateSampler
    {
    public:
        /** Samples in space, which must outlive the sampler (PhysicsStateSpace makes it). */
        explicit PhysicsStateSampler(const PhysicsStateSpace *space);

        /** OMPL's hook: the robot uniform in its region (at its start height) with a uniform
            horizontal velocity, the movable bodies at rest at their start poses. */
        void sampleUniform(ompl::base::State *state) override;

        /** Copies near and moves the robot uniformly within distance (m) along x and y, clamped to
            its region. */
        void sampleUniformNear(ompl::base::State *state, const ompl::base::State *near,
                               double distance) override;

        /** Copies mean and moves the robot by a normal offset of standard deviation stdDev (m) along x
            and y, clamped to its region. */
        void sampleGaussian(ompl::base::State *state, const ompl::base::State *mean, double stdDev) override;

    private:
        void moveRobot(ompl::base::State *state, const Eigen::Vector2d &offset);

        const PhysicsStateSpace &physics_;
        std::vector<std::size_t> movable_;
        BodyStates scratch_;
    };
}  // namespace ompl_phys
