#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstdint>
#include <vector>

namespace ompl_mm
{
    /** Several MOPL searches of one problem racing on the cores a user has, one thread each: the
        heavy tail of one search's time is cut by the others (the search that is lucky finishes
        first). Each search runs on its own ManipulationSetup (the collision world, the primitives'
        inverse kinematics and the planner's scratch space are per setup, not shared), built from
        the same scene and seeded apart (seedOf()).
        Deterministic: the winner is the search that solved in the fewest iterations (ties: the
        lower index), not the first to finish in time, so the same setups and seeds give the same
        winner and path whatever the threads' timing. A search stops as soon as its iteration count
        shows that it can no longer win; the race waits for those still below the best count. Only
        the time limit itself (the caller's condition) can make the outcome depend on timing, as for
        one search. */
    class MoplRace
    {
    public:
        /** Most searches in one race. */
        static constexpr unsigned int MAX_SEARCHES = 64;

        /** The seed of search `index` of a race seeded with `seed`: search 0 keeps the seed, so a race
            of one is the plain search. */
        static std::uint_fast32_t seedOf(std::uint_fast32_t seed, unsigned int index);

        /** Sets up every setup, then solves all of them at once, one thread each, until ptc or until
            the race is decided. @returns the index of the winning setup (its problem definition
            holds the solution, its planner the statistics), or -1 when none solved.
            @pre each setup's planner is MOPL, seeded by the caller (seedOf()); 1 to MAX_SEARCHES
            setups. @throws ompl::Exception when a planner is not MOPL or the count is out of range. */
        static int solve(const std::vector<ManipulationSetup *> &setups,
                         const ompl::base::PlannerTerminationCondition &ptc);
    };
}  // namespace ompl_mm
