#pragma once

#include <memory>

#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"

#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/util/RandomNumbers.h>

namespace ompl_phys
{
    /** The goal of a physics scene: the robot centre within a disc on the floor, whatever the bodies
        and velocities. Goal samples are proper states, not random ones: the robot at rest at a
        uniform point of the disc, the bodies at their start poses except those on the goal, which
        the manipulation knowledge moves out of the robot's way. So goal bias steers planners
        towards the goal and, when the goal is occupied, towards clearing it. */
    class PhysicsGoal : public ompl::base::GoalSampleableRegion
    {
    public:
        /** Spare distance between the robot on the goal and a body moved off it, m. */
        static constexpr double CLEARANCE = 0.02;

        /** The goal of the scene of si's space, which must be a PhysicsStateSpace. startStates: every
            moving body at the start, copied; the goal shares knowledge, which it keeps alive. */
        PhysicsGoal(const ompl::base::SpaceInformationPtr &si,
                    std::shared_ptr<const ManipulationKnowledge> knowledge, BodyStates startStates);

        /** Distance of the robot centre from the disc's centre, m; satisfied up to the disc's radius
            (the goal's threshold). */
        double distanceGoal(const ompl::base::State *state) const override;

        /** OMPL's hook: the robot at rest at a uniform point of the disc, the start bodies with the
            goal's occupants moved CLEARANCE beyond the robot there. */
        void sampleGoal(ompl::base::State *state) const override;

        /** Unlimited: every sample is a new point of the disc. */
        unsigned int maxSampleCount() const override;

    private:
        const PhysicsStateSpace &space_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
        BodyStates start_;
        Eigen::Vector2d centre_;
        mutable ompl::RNG rng_;
    };
}  // namespace ompl_phys
