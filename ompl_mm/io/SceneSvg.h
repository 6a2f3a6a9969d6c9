#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <ostream>

namespace ompl_mm
{
    /** Writes an SVG picture of the setup's scene and, when given, its solution. The top view
        (x right, y up) shows obstacles and support surfaces, objects at the start (outlined) and
        at the end of the path (filled), the goals, the tool's path coloured by primitive, pushes
        drawn as arrows and a mobile robot (all joints prismatic) at the start and the end; for such
        a robot it is the whole picture. For an arm (any other robot) the top view also shows the
        arm's link shapes from above, and a side view (x right, z up, seen from -y; its own scale)
        stands to the right of the top view, each under a caption ("top view (x–y)", "side view
        (x–z)") with its own scale bar: obstacles as the outlines of their shapes, surfaces edge-on
        at their height, the objects at the start and the end, the arm's link shapes at the start,
        at every mode switch (a waypoint where the segments' primitive or object changes) and at
        the end, faint to solid in the path's order (each a group of class "arm-pose", in both
        views), the tool's path coloured by primitive and, inside it, the course of each
        transferred object's centre in the object's colour. Shapes are outlined as the convex hulls
        of their projections (a mesh's: of its vertices'; a sphere as a circle); the arm is drawn
        by its collision shapes. Labels (goals, objects where they end and start, the mobile robot)
        are placed by a LabelLayout so that none covers another or a goal symbol; one that finds no
        free place is left out. path may be null (scene only: the arm at the start alone).
        @throws ompl::Exception when the setup has no start state. */
    void writeSceneSvg(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path);
}  // namespace ompl_mm
