#pragma once

#include "ompl_core/run/RunRecord.h"
#include "ompl_mm/setup/ManipulationSetup.h"

namespace ompl_mm
{
    /** The record of the setup's last solve(), which run describes (see docs/user-guide.md for the
        JSON that ompl_mm_plan writes from it): tree sizes, MOPL's statistics when the planner is
        MOPL, and for solved runs the Cartesian tool-path length (metres), the path's vertices,
        whether it passes OMPL's PathGeometric::check() and its primitives by kind.
        @pre solve() has been called. */
    ompl_core::RunResult manipulationRunResult(const ompl_core::RunDescription &run,
                                               const ManipulationSetup &setup);
}  // namespace ompl_mm
