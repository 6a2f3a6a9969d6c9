#pragma once

#include "ompl_core/run/RunRecord.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <optional>

namespace ompl_mm
{
    /** The record of the setup's last solve(), which run describes (see docs/user-guide.md for the
        JSON that ompl_mm_plan writes from it): tree sizes, MOPL's statistics when the planner is
        MOPL, and for solved runs the Cartesian tool-path length (metres), the path's vertices,
        whether it passes OMPL's PathGeometric::check() and its primitives by kind. pathValid is
        that check's result when the caller has made it already on the same path (ompl_mm_plan
        does, before printing its summary): a check of every motion near triangle meshes takes
        a while, and the same path gives the same answer; without it the check is made here.
        @pre solve() has been called. */
    ompl_core::RunResult manipulationRunResult(const ompl_core::RunDescription &run,
                                               const ManipulationSetup &setup,
                                               std::optional<bool> pathValid = std::nullopt);
}  // namespace ompl_mm
