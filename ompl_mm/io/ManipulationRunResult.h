/* The record of one MOPL run on a ManipulationSetup (see docs/user-guide.md for the JSON that
   ompl_mm_plan writes from it): tree sizes, the planner's statistics, and for solved runs the
   Cartesian tool-path length, the path's vertices and its primitives by kind. */
#pragma once

#include "ompl_core/run/RunRecord.h"
#include "ompl_mm/setup/ManipulationSetup.h"

namespace ompl_mm
{
    /** The result of the setup's last solve(), which run describes. */
    ompl_core::RunResult manipulationRunResult(const ompl_core::RunDescription &run,
                                               const ManipulationSetup &setup);
}  // namespace ompl_mm
