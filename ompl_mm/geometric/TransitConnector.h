#pragma once

#include "ompl_mm/primitives/Trajectory.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/util/RandomNumbers.h>

namespace ompl_mm
{
    /** Connects two robot configurations while every object stays where it is: the straight
        transit when it is valid, else a bidirectional RRT (RRT-Connect) in the robot's joint space
        with a bounded number of iterations, drawing from the caller's RNG so that results repeat
        per seed, its path then shortened greedily. Motions are checked by the space information's
        motion validator. ManipulationSimplifier uses it to route the robot around an object that
        it no longer moves. */
    class TransitConnector
    {
    public:
        /** A connector for states of si, whose state space must be a ManipulationStateSpace. */
        explicit TransitConnector(ompl::base::SpaceInformationPtr si);

        /** Appends transit waypoints to trajectory from its last state to `to`, which must differ
            from it in the robot's joints only, within maxIterations RRT iterations and before ptc
            is true; appends nothing and returns false when that fails. (Its motion checks stop at
            ptc only through the validator: see ManipulationMotionValidator::TerminationScope.) */
        bool connect(Trajectory &trajectory, const ompl::base::State *to, unsigned int maxIterations,
                     ompl::RNG &rng,
                     const ompl::base::PlannerTerminationCondition &ptc =
                         ompl::base::plannerNonTerminatingCondition()) const;

        /** Longest joint-space step of one RRT extension: a tenth of the joint space's extent. */
        double range() const { return range_; }

    private:
        struct Node
        {
            ompl::base::State *state;
            int parent;
        };
        using Tree = std::vector<Node>;

        /** Index of the node of tree nearest to state in joint space. */
        int nearest(const Tree &tree, const ompl::base::State *state) const;
        /** Grows tree from its node nearest to target by at most range() towards it; returns the
            new node's index, or -1 when the motion is invalid. */
        int extend(Tree &tree, const ompl::base::State *target) const;
        /** The states from a tree's root to node, root first. */
        static std::vector<const ompl::base::State *> branch(const Tree &tree, int node);

        ompl::base::SpaceInformationPtr si_;
        const ManipulationStateSpace *space_;
        double range_;
    };
}  // namespace ompl_mm
