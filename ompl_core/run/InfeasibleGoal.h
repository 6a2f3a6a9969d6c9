/* The answer of a setup's solve() to a goal found impossible before planning. */
#pragma once

#include "ompl_core/io/InputError.h"

#include <ompl/base/PlannerStatus.h>

#include <string>

namespace ompl_core
{
    /** Logs "<setupName>: <fault>" as an OMPL error and returns infeasibleStatus(): INFEASIBLE in
        OMPL 1.6 and later, INVALID_GOAL in OMPL 1.5. For setups whose checks before planning
        found that no motion reaches the goal (fault names the scene line of the goal), so that
        solve() answers at once with OMPL's status instead of planning to its time limit. */
    ompl::base::PlannerStatus infeasibleGoal(const std::string &setupName, const InputError &fault);
}  // namespace ompl_core
