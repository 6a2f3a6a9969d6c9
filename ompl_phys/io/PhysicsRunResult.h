#pragma once

#include "ompl_core/run/RunRecord.h"
#include "ompl_phys/control/PathSimulation.h"

namespace ompl_phys
{
    /** The record of one physics planning run: the result of the setup's last solve(), which run
        describes (see docs/user-guide.md for the JSON that ompl_phys_plan writes from it). Its
        details hold what occupies the goal at the start (goal_occupied_by), propagation counters,
        stops by violation and the tree size (stats), and for solved runs the re-simulation
        (reaches_goal, violation, moves, steps, duration_s) with action, power and smoothness.
        simulated is the re-simulation of the solution path (null when unsolved or not
        re-simulated; its values are then left out).
        @pre solve() has run on setup, so it has a planner and a last status. */
    ompl_core::RunResult physicsRunResult(const ompl_core::RunDescription &run, const PhysicsSetup &setup,
                                          const SimulatedPath *simulated);
}  // namespace ompl_phys
