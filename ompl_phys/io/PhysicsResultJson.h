/* The JSON result of one physics planning run, as ompl_phys_plan writes it (see
   docs/user-guide.md): scene, planner, seed, solved, time_s, stats {propagations, sub-steps,
   stops by violation, tree size}, goal_occupied_by, and for solved runs the re-simulation
   (reaches_goal, steps, duration_s, moves) with action, power and smoothness. */
#pragma once

#include "ompl_mm/io/ResultJson.h"
#include "ompl_phys/control/PathSimulation.h"

#include <ostream>

namespace ompl_phys
{
    /** Writes the result of the setup's last solve(); simulated is the re-simulation of its solution
        path (null when unsolved). */
    void writePhysicsResultJson(std::ostream &out, const ompl_mm::RunDescription &run,
                                const PhysicsSetup &setup, const SimulatedPath *simulated);
}  // namespace ompl_phys
