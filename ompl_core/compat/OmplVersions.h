/* What differs between the OMPL versions the project builds against (1.5.2 to 2.0.x), in one
   place: OMPL_VERSION_VALUE is major * 1000000 + minor * 1000 + patch. */
#pragma once

#include <ompl/base/PlannerStatus.h>
#include <ompl/config.h>
#include <ompl/geometric/PathSimplifier.h>

namespace ompl_core
{
    /** The status of a problem found impossible before planning (a goal no motion can reach):
        INFEASIBLE where OMPL has it (1.6 and later), INVALID_GOAL in OMPL 1.5. */
    constexpr ompl::base::PlannerStatus::StatusType infeasibleStatus()
    {
#if OMPL_VERSION_VALUE >= 1006000
        return ompl::base::PlannerStatus::INFEASIBLE;
#else
        return ompl::base::PlannerStatus::INVALID_GOAL;
#endif
    }

    /** One pass of OMPL's random shortcutting (Partial-Shortcut, Geraerts and Overmars 2004) with
        its default steps: PathSimplifier::shortcutPath up to OMPL 1.6, partialShortcutPath since
        1.7, the same algorithm. Returns whether path changed. */
    inline bool partialShortcut(ompl::geometric::PathSimplifier &simplifier,
                                ompl::geometric::PathGeometric &path)
    {
#if OMPL_VERSION_VALUE >= 1007000
        return simplifier.partialShortcutPath(path);
#else
        return simplifier.shortcutPath(path);
#endif
    }

    /** OMPL's deterministic RRT-Rope shortcutting (Petit and Desbiens 2021) with its default
        steps where OMPL has it (1.7 and later); in older OMPL the path stays as it is. Returns
        whether path changed. */
    inline bool ropeShortcut([[maybe_unused]] ompl::geometric::PathSimplifier &simplifier,
                             [[maybe_unused]] ompl::geometric::PathGeometric &path)
    {
#if OMPL_VERSION_VALUE >= 1007000
        return simplifier.ropeShortcutPath(path);
#else
        return false;
#endif
    }
}  // namespace ompl_core
