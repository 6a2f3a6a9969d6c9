/* A manipulation path as text: a header naming the columns, then one line per waypoint with the
   label of the segment that reached it ("start" for the first), the robot's joints, and each
   object's x y z yaw. Easy to read back with numpy.loadtxt(..., usecols=...) or a spreadsheet. */
#pragma once

#include "ompl_mm/geometric/ManipulationPath.h"

#include <ostream>

namespace ompl_mm
{
    void writePathFile(std::ostream &out, const ManipulationPath &path);
}  // namespace ompl_mm
