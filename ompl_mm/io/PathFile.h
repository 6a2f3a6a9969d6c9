#pragma once

#include "ompl_mm/geometric/ManipulationPath.h"

#include <ostream>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** Columns a caller adds to a path file after the planned ones: their names, and per waypoint
        one value per name. */
    struct ExtraColumns
    {
        std::vector<std::string> names;           ///< header names, without spaces
        std::vector<std::vector<double>> values;  ///< per waypoint, one value per name
    };

    /** Writes a manipulation path as text: a header naming the columns, then one line per waypoint
        with the label of the segment that reached it (primitive kind and object name, "start -" for
        the first), the tool point's world x y z (metres), the robot's joints, and each object's
        x y z yaw (metres, radians), then the extra columns. Easy to read back with
        numpy.loadtxt(..., usecols=...) or a spreadsheet.
        @throws ompl::Exception when extra has values but not one row of names.size() values per
        waypoint. */
    void writePathFile(std::ostream &out, const ManipulationPath &path, const ExtraColumns &extra = {});
}  // namespace ompl_mm
