/* Ctrl-C in the apps: it ends a planning run, after which the app still writes what it found. */
#pragma once

#include <ompl/base/PlannerTerminationCondition.h>

#include <atomic>
#include <csignal>

namespace apps
{
    namespace detail
    {
        inline std::atomic<bool> interrupted{false};

        inline void onInterrupt(int)
        {
            interrupted = true;
        }
    }  // namespace detail

    /** True once SIGINT (Ctrl-C) has come. Installs the SIGINT handler. */
    inline ompl::base::PlannerTerminationCondition interruptCondition()
    {
        std::signal(SIGINT, detail::onInterrupt);
        return ompl::base::PlannerTerminationCondition([] { return detail::interrupted.load(); });
    }
}  // namespace apps
