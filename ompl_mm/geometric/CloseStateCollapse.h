#pragma once

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>

namespace ompl_mm
{
    /** OMPL's PathSimplifier::collapseCloseVertices() with its defaults, step for step (the same
        path results), but stopping at ptc: repeatedly joins the closest two states of the path
        that are not neighbours by a direct motion when the motion validator accepts it, dropping
        the states between them; a pair that fails is not tried again. OMPL's own keeps the
        distances in a map and scans it for every step, so that on a path of a few hundred states
        it runs for a tenth of a second and more without asking its caller; here a table does,
        and ptc is asked before every step and every row of distances. Returns true when the
        path changed. */
    bool collapseCloseStates(ompl::geometric::PathGeometric &path,
                             const ompl::base::PlannerTerminationCondition &ptc);
}  // namespace ompl_mm
