#include "ompl_core/run/TimeLimit.h"

#include <cmath>

namespace ompl_core
{
    ompl::base::PlannerTerminationCondition timeLimitOr(double seconds,
                                                        const ompl::base::PlannerTerminationCondition &stop)
    {
        if (!std::isfinite(seconds) || seconds > LONGEST_TIME_LIMIT)
            return stop;
        return ompl::base::plannerOrTerminationCondition(
            ompl::base::timedPlannerTerminationCondition(seconds), stop);
    }
}  // namespace ompl_core
