#pragma once

#include "ompl_mm/primitives/Primitive.h"
#include "ompl_mm/primitives/PrimitiveTally.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <vector>

namespace ompl_mm
{
    /** The empty-space planner (ESP) of MOPL: chains useful primitives from a start towards a
        target configuration as if there were no obstacles. Primitives are tried in a shuffled order
        in passes; a primitive that fails is skipped until another one succeeds; planning stops when
        a pass finds nothing useful left to try. Collisions are checked by the caller. Shares its
        primitives; not thread-safe (plan() reuses scratch space). */
    class EmptySpacePlanner
    {
    public:
        /** How far plan() got. */
        enum class Outcome
        {
            Reached,       ///< the trajectory ends at the target
            Partial,       ///< it moved, but no primitive could finish
            AlreadyThere,  ///< start equals target
            Failed         ///< no primitive could move at all
        };

        /** Bound on primitive applications per call, so a cycle of primitives cannot hang it. */
        static constexpr unsigned int MAX_STEPS = 64;

        /** A planner chaining primitives in space. @pre space outlives the planner. */
        EmptySpacePlanner(const ManipulationStateSpace *space, std::vector<PrimitivePtr> primitives);

        /** The primitives it chains. */
        const std::vector<PrimitivePtr> &primitives() const { return primitives_; }

        /** How its primitives fared in plan() so far (attempts, and why they found no motion);
            callers that check the motions note them here too (PrimitiveTally::motion). */
        PrimitiveTally &tally() { return tally_; }
        /** As tally(), read-only. */
        const PrimitiveTally &tally() const { return tally_; }

        /** Plans from `from` towards `to` with at most MAX_STEPS primitive applications, drawing
            the order of the primitives from rng; trajectory is reset to start at from and holds the
            waypoints found, whatever the outcome. Once ptc is true it stops before the next
            primitive application and within one (Primitive::propagate with ptc), with the outcome of
            the waypoints found so far (Partial or Failed). A primitive that does not end where
            asked (Primitive::endsWhereAsked) is left out when exactOnly is true; otherwise the
            objects it moves count as done where it left them, so that the other primitives go
            on towards the rest of `to` (then the outcome is Partial, as `to` itself is missed). */
        Outcome plan(
            const ompl::base::State *from, const ompl::base::State *to, Trajectory &trajectory,
            ompl::RNG &rng,
            const ompl::base::PlannerTerminationCondition &ptc = ompl::base::plannerNonTerminatingCondition(),
            bool exactOnly = false);

    private:
        /** Takes into target the pose of every object that moved from `before` to `after`. */
        void adoptMovedObjects(const ompl::base::State *before, const ompl::base::State *after,
                               ompl::base::State *target) const;

        PrimitiveTally tally_;
        const ManipulationStateSpace *space_;
        std::vector<PrimitivePtr> primitives_;
        std::vector<std::size_t> order_;
        std::vector<char> failed_;
    };
}  // namespace ompl_mm
