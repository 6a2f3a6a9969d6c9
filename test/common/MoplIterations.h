// Shared test helper: a termination condition that bounds MOPL by the iterations of its search loop.
#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstdint>
#include <memory>

namespace ompl_mm::test
{
    /** Ends the setup's MOPL search once it has run `iterations` iterations since the planner's last
        clear(). Unlike OMPL's IterationTerminationCondition, which counts its evaluations, it does
        not run out sooner when MOPL also polls it inside long steps (as it does every millisecond
        of a step, to keep time limits): the same seed gives the same search on a fast build and
        under the sanitizers. @pre the setup's planner is MOPL. */
    inline ompl::base::PlannerTerminationCondition moplIterations(const ManipulationSetup &setup,
                                                                  std::uint64_t iterations)
    {
        const std::shared_ptr<MOPL> mopl = setup.mopl();
        return ompl::base::PlannerTerminationCondition(
            [mopl, iterations] { return mopl->statistics().iterations >= iterations; });
    }
}  // namespace ompl_mm::test
