#pragma once

#include "ompl_core/io/PlanViewer.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <ostream>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** How fast a plan page plays a path: the tool point (or, where it rests, the joints and objects)
        moves this many metres (or radians) per second. */
    constexpr double VIEWER_SPEED = 0.5;

    /** The objects' poses at every waypoint of a path from another source than the plan (an
        execution in physics, say), for the plan page to show beside the planned ones. */
    struct CompanionPoses
    {
        std::string label;  ///< what they are, for the legend and the bodies' names ("simulated")
        std::vector<std::vector<ObjectPose>> poses;  ///< per waypoint, one pose per object
    };

    /** The 3-D view of the setup's scene and, when given, its solution: obstacles (floor slabs
        light), support surfaces (tinted), the robot posed by forward kinematics, the objects, the
        goals (translucent), and the path sampled every ViewerPlan::frameStep at VIEWER_SPEED along
        the state space's interpolation (so a held object moves with the hand, a pushed one with the
        tool), its tool path coloured by primitive as in the SVG. The robot shows its URDF's visual
        geometry in its colours (VisualModel, read here, not at planning time), or its collision
        shapes for links without; meshes of more than MeshReduction::maxVertices vertices are
        reduced (reduceMesh()), each mesh once for all the solids that use it. path may be null
        (the start only). With companions (one entry per waypoint of path), each object also has a
        translucent companion posed by them (between waypoints as the plan's frames interpolate),
        and the courses of the objects and their companions are drawn.
        @throws ompl::Exception when the setup has no start state; ompl_core::InputError as
        VisualModel::fromUrdfFile() for a malformed visual (a missing visual mesh is a warning). */
    ompl_core::ViewerPlan manipulationViewerPlan(const ManipulationSetup &setup, const ManipulationPath *path,
                                                 const std::string &title,
                                                 const CompanionPoses *companions = nullptr);

    /** Writes manipulationViewerPlan() as a self-contained HTML page (ompl_core::writePlanViewerPage()).
        @throws ompl_core::InputError when three.js is missing, ompl::Exception as manipulationViewerPlan().
     */
    void writeSceneHtml(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path,
                        const std::string &title, const CompanionPoses *companions = nullptr);
}  // namespace ompl_mm
