#pragma once

#include "ompl_core/io/PlanViewer.h"
#include "ompl_phys/control/PathSimulation.h"

#include <ostream>
#include <string>

namespace ompl_phys
{
    /** The 3-D view of the setup's scene and, when given, a re-simulated solution: the floor, fixed
        bodies (prisms as meshes), the goal disc (translucent), the robot and the movable bodies posed
        at every simulation step, and their courses. The timeline is split where the set of bodies
        the robot moves changes ("push cube3", "transit"), coloured as the MOPL pages. simulated may
        be null (the start only). */
    ompl_core::ViewerPlan physicsViewerPlan(const PhysicsSetup &setup, const SimulatedPath *simulated,
                                            const std::string &title);

    /** Writes physicsViewerPlan() as a self-contained HTML page (ompl_core::writePlanViewerPage()).
        @throws ompl_core::InputError when three.js is missing. */
    void writePhysicsSceneHtml(std::ostream &out, const PhysicsSetup &setup, const SimulatedPath *simulated,
                               const std::string &title);
}  // namespace ompl_phys
