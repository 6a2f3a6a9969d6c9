/* When a planning run of the apps ends: at its time limit, or at Ctrl-C. */
#pragma once

#include <ompl/base/PlannerTerminationCondition.h>

#include <atomic>
#include <cmath>
#include <csignal>

namespace apps
{
    /** A time limit above this many seconds (or infinite) means no limit: OMPL's clock would overflow
        for limits beyond about 292 years, ending the run at once. */
    constexpr double LONGEST_TIME_LIMIT = 1e8;

    namespace detail
    {
        inline std::atomic<bool> interrupted{false};

        inline void onInterrupt(int)
        {
            interrupted = true;
        }
    }  // namespace detail

    /** The condition that ends planning: the time limit in seconds (none when infinite or above
        LONGEST_TIME_LIMIT) or SIGINT (Ctrl-C), after which the app still writes what it found.
        Installs the SIGINT handler. */
    inline ompl::base::PlannerTerminationCondition runTermination(double seconds)
    {
        std::signal(SIGINT, detail::onInterrupt);
        const ompl::base::PlannerTerminationCondition interrupt([] { return detail::interrupted.load(); });
        if (!std::isfinite(seconds) || seconds > LONGEST_TIME_LIMIT)
            return interrupt;
        return ompl::base::plannerOrTerminationCondition(
            ompl::base::timedPlannerTerminationCondition(seconds), interrupt);
    }
}  // namespace apps
