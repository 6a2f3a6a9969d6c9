#pragma once

#include "ompl_phys/control/PathSimulation.h"

#include <ostream>

namespace ompl_phys
{
    /** Writes the re-simulation of a solution as text, so that its metrics and its end can be
        recomputed without ODE: a first line "# step_s H goal_x X goal_y Y goal_radius R", a line
        naming the columns, then one line per sample k = 0 … n: k, its time (s), the index of the
        move applied from this sample to the next (-1 for the last sample) with that move's force
        fx fy fz (N, world frame; 0 for the last sample), then x y z of the robot centre and of every movable
       body (m, world frame). Numbers have 17 significant digits, so they read back exactly.
        @pre simulated is simulatePath() of a path planned on setup. */
    void writeSimulatedPathFile(std::ostream &out, const PhysicsSetup &setup, const SimulatedPath &simulated);
}  // namespace ompl_phys
