#pragma once

#include "ompl_core/io/PlanViewer.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <ostream>
#include <string>

namespace ompl_mm
{
    /** How fast a plan page plays a path: the tool point (or, where it rests, the joints and objects)
        moves this many metres (or radians) per second. */
    constexpr double VIEWER_SPEED = 0.5;

    /** The 3-D view of the setup's scene and, when given, its solution: obstacles, support surfaces
        (tinted), the robot's collision shapes posed by forward kinematics, the objects, the goals
        (translucent), and the path sampled every ViewerPlan::frameStep at VIEWER_SPEED along the
        state space's interpolation (so a held object moves with the hand, a pushed one with the
        tool), its tool path coloured by primitive as in the SVG. path may be null (the start only).
        @throws ompl::Exception when the setup has no start state. */
    ompl_core::ViewerPlan manipulationViewerPlan(const ManipulationSetup &setup, const ManipulationPath *path,
                                                 const std::string &title);

    /** Writes manipulationViewerPlan() as a self-contained HTML page (ompl_core::writePlanViewerPage()).
        @throws ompl_core::InputError when three.js is missing, ompl::Exception as manipulationViewerPlan().
     */
    void writeSceneHtml(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path,
                        const std::string &title);
}  // namespace ompl_mm
