#pragma once

#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/geometric/PathRouter.h"
#include "ompl_mm/primitives/EmptySpacePlanner.h"

#include <ompl/base/Goal.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <memory>

namespace ompl_mm
{
    /** Removes push reversals (ManipulationPath::pushReversals: a push moving an object back
        against the push of it before), one of ManipulationSimplifier's steps. Three ways, in turn:
        the earlier push run ended where it comes nearest to where the later push leaves the
        object (endReversal); else the object pushed once, from where the earlier push began, to
        where the later pushes leave it (pushOnceInstead); else pushed aside by the later run
        instead of back (pushAside). The object stays where a way leaves it meanwhile,
        the robot routed around it (PathRouter). Deterministic for a given RNG state; not
        thread-safe (it reuses its empty-space planner's scratch space). */
    class PushReversalRemover
    {
    public:
        /** A remover for paths in si, with the primitives of validator (which checks the motions). */
        PushReversalRemover(const ompl::base::SpaceInformationPtr &si,
                            const std::shared_ptr<ManipulationMotionValidator> &validator);

        /** Ends each push reversal of path that it can: the first way after which the path has
            fewer reversals (a way's new pushes may reverse too), else the first after which it has
            as many; the last reversal first (each tried once, until ptc is true). goal (may be
            null: then no way may change the path's end) tells whether a changed end still solves
            the problem. Returns how many were removed. */
        unsigned int remove(ManipulationPath &path, const ompl::base::Goal *goal, ompl::RNG &rng,
                            const ompl::base::PlannerTerminationCondition &ptc) const;

    private:
        /** Ends the reversal's earlier push run (the consecutive pushes of the object up to the
            earlier push) where it comes nearest to where the later push leaves the object, keeps
            the object there until the later push, and moves it from there to that end with the
            empty-space planner's primitives (none when it is there already),
            the robot routed around the object where its old motions meet it. True when every
            motion of that is valid (the path then changed; its states after the later push stay
            as they were). */
        bool endReversal(ManipulationPath &path, const ManipulationPath::PushReversal &reversal,
                         ompl::RNG &rng, const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Instead of the reversal's earlier push and the later push run, pushes the object from
            where the earlier push begins straight to where that run leaves it (the empty-space
            planner's primitives), then takes the robot on along its old way, the object staying
            there, routed around it where the old motions meet it. True when every motion of that
            is valid (the path then changed; its states after the later run stay as they were). */
        bool pushOnceInstead(ManipulationPath &path, const ManipulationPath::PushReversal &reversal,
                             ompl::RNG &rng, const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Instead of the reversal's later push run, pushes the object aside from where that run
            finds it, in a direction at most a right angle from the earlier push's (those nearest
            the run's own first), as far as the run or the earlier push moves it, and leaves it
            there for the rest of the way (later pushes of it become the robot's transits), the
            robot routed around it where its old motions meet it. True when every motion of that
            is valid and the end still satisfies goal (the path then changed). */
        bool pushAside(ManipulationPath &path, const ManipulationPath::PushReversal &reversal,
                       const ompl::base::Goal *goal, ompl::RNG &rng,
                       const ompl::base::PlannerTerminationCondition &ptc) const;

        ompl::base::SpaceInformationPtr si_;
        const ManipulationStateSpace *space_;
        PathRouter router_;
        mutable EmptySpacePlanner planner_;
    };
}  // namespace ompl_mm
