/* Which parameter settings of a benchmark config each planner gets. */
#pragma once

#include "ompl_core/bench/BenchmarkConfig.h"

#include <ompl/base/Planner.h>

#include <vector>

namespace ompl_core
{
    /** The settings planner gets from a config: the problem's parameters that it declares, then the
        planner entry's own (so those win). */
    std::vector<ParameterSetting> benchmarkSettings(const ompl::base::Planner &planner,
                                                    const BenchmarkProblem &problem,
                                                    const BenchmarkPlanner &entry);

    /** @throws InputError at the line of the first parameter of problem that none of planners
        declares (a misspelt key, say). */
    void requireProblemParametersUsed(const BenchmarkProblem &problem,
                                      const std::vector<ompl::base::PlannerPtr> &planners);
}  // namespace ompl_core
