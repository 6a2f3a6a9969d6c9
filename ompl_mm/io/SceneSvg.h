#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <ostream>

namespace ompl_mm
{
    /** Writes an SVG picture of the setup's scene and, when given, its solution. The top view
        (x right, y up) shows obstacles and support surfaces, objects at the start (outlined) and
        at the end of the path (filled), the goals, the tool's path coloured by primitive, pushes
        drawn as arrows and a mobile robot (all joints prismatic) at the start and the end; for such
        a robot it is the whole picture. For an arm (any other robot) a side view (x right, z up,
        seen from -y; its own scale) stands to the right of the top view, each under a caption
        ("top view (x–y)", "side view (x–z)") with its own scale bar: obstacles as the outlines of
        their shapes (boxes and meshes by their bounding boxes), surfaces edge-on at their height,
        the objects at the start and the end, the arm's link shapes at the start, at every mode
        switch (a waypoint where the segments' primitive or object changes) and at the end, faint
        to solid in the path's order (each a group of class "arm-pose"), the tool's path coloured
        by primitive and, inside it, the course of each transferred object's centre in the
        object's colour. path may be null (scene only: the arm at the start alone).
        @throws ompl::Exception when the setup has no start state. */
    void writeSceneSvg(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path);
}  // namespace ompl_mm
