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

    /** The 3-D view of the setup's scene and, when given, its solution: obstacles (floor slabs
        light), support surfaces (tinted), the robot posed by forward kinematics, the objects, the
        goals (translucent), and the path sampled every ViewerPlan::frameStep at VIEWER_SPEED along
        the state space's interpolation (so a held object moves with the hand, a pushed one with the
        tool), its tool path coloured by primitive as in the SVG. The robot shows its URDF's visual
        geometry in its colours (VisualModel, read here, not at planning time), or its collision
        shapes for links without; meshes of more than MeshReduction::maxVertices vertices are
        reduced (reduceMesh()), each mesh once for all the solids that use it. path may be null
        (the start only).
        @throws ompl::Exception when the setup has no start state; ompl_core::InputError as
        VisualModel::fromUrdfFile() for a malformed visual (a missing visual mesh is a warning). */
    ompl_core::ViewerPlan manipulationViewerPlan(const ManipulationSetup &setup, const ManipulationPath *path,
                                                 const std::string &title);

    /** Writes manipulationViewerPlan() as a self-contained HTML page (ompl_core::writePlanViewerPage()).
        @throws ompl_core::InputError when three.js is missing, ompl::Exception as manipulationViewerPlan().
     */
    void writeSceneHtml(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path,
                        const std::string &title);
}  // namespace ompl_mm
