#pragma once

#include "ompl_mm/geometric/ManipulationPath.h"

#include <ostream>

namespace ompl_mm
{
    /** Writes a manipulation path as text: a header naming the columns, then one line per waypoint
        with the label of the segment that reached it (primitive kind and object name, "start -" for
        the first), the tool point's world x y z (metres), the robot's joints, and each object's
        x y z yaw (metres, radians). Easy to read
        back with numpy.loadtxt(..., usecols=...) or a spreadsheet. */
    void writePathFile(std::ostream &out, const ManipulationPath &path);
}  // namespace ompl_mm
