#include "ompl_core/run/InfeasibleGoal.h"

#include "ompl_core/compat/OmplVersions.h"

#include <ompl/util/Console.h>

namespace ompl_core
{
    ompl::base::PlannerStatus infeasibleGoal(const std::string &setupName, const InputError &fault)
    {
        OMPL_ERROR("%s: %s", setupName.c_str(), fault.what());
        return infeasibleStatus();
    }
}  // namespace ompl_core
