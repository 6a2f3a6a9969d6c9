#pragma once

#include "ompl_phys/control/PathSimulation.h"

#include <ostream>
#include <string>

namespace ompl_phys
{
    /** Writes a top-down SVG picture of the setup's scene and, when given, a re-simulated solution:
        the floor, fixed bodies (grey), movable bodies at the start (outlined) and at the end
        (filled; constraint-oriented ones with their push axis), the goal disc, the robot's
        trajectory, and the trajectories of the bodies it pushed. simulated may be null (scene
        only); title is printed at the top. */
    void writePhysicsSceneSvg(std::ostream &out, const PhysicsSetup &setup, const SimulatedPath *simulated,
                              const std::string &title);
}  // namespace ompl_phys
