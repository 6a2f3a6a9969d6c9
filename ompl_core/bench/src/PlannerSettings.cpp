#include "ompl_core/bench/PlannerSettings.h"

#include "ompl_core/io/InputError.h"

#include <algorithm>

namespace ompl_core
{
    std::vector<ParameterSetting> benchmarkSettings(const ompl::base::Planner &planner,
                                                    const BenchmarkProblem &problem,
                                                    const BenchmarkPlanner &entry)
    {
        std::vector<ParameterSetting> settings;
        for (const ParameterSetting &setting : problem.parameters)
            if (planner.params().hasParam(setting.name))
                settings.push_back(setting);
        settings.insert(settings.end(), entry.parameters.begin(), entry.parameters.end());
        return settings;
    }

    void requireProblemParametersUsed(const BenchmarkProblem &problem,
                                      const std::vector<ompl::base::PlannerPtr> &planners)
    {
        for (const ParameterSetting &setting : problem.parameters)
            if (std::none_of(planners.begin(), planners.end(),
                             [&](const ompl::base::PlannerPtr &p)
                             { return p->params().hasParam(setting.name); }))
                throw InputError(setting.where,
                                 "unknown key '" + setting.name +
                                     "' in [problem]: neither name, scene nor time_limit, and no "
                                     "planner of this config declares such a parameter");
    }
}  // namespace ompl_core
