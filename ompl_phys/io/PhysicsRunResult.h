/* The record of one physics planning run (see docs/user-guide.md for the JSON that
   ompl_phys_plan writes from it): what occupies the goal, propagation counters and stops by
   violation, the tree size, and for solved runs the re-simulation (reaches_goal, violation,
   moves, steps, duration_s) with action, power and smoothness. */
#pragma once

#include "ompl_core/run/RunRecord.h"
#include "ompl_phys/control/PathSimulation.h"

namespace ompl_phys
{
    /** The result of the setup's last solve(), which run describes; simulated is the
        re-simulation of its solution path (null when unsolved). */
    ompl_core::RunResult physicsRunResult(const ompl_core::RunDescription &run, const PhysicsSetup &setup,
                                          const SimulatedPath *simulated);
}  // namespace ompl_phys
