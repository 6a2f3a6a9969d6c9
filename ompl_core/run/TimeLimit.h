/* A planning run's time limit as an OMPL termination condition. */
#pragma once

#include <ompl/base/PlannerTerminationCondition.h>

namespace ompl_core
{
    /** A time limit above this many seconds (or infinite) means no limit: OMPL's clock would overflow
        for limits beyond about 292 years, ending the run at once. */
    constexpr double LONGEST_TIME_LIMIT = 1e8;

    /** True after `seconds` (never when infinite or above LONGEST_TIME_LIMIT) or once stop is true
        (Ctrl-C in the apps, Python's signals in the modules). */
    ompl::base::PlannerTerminationCondition timeLimitOr(double seconds,
                                                        const ompl::base::PlannerTerminationCondition &stop);
}  // namespace ompl_core
