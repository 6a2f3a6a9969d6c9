/* The JSON result of one planning run, as ompl_mm_plan writes it (see docs/user-guide.md):
   scene, planner, seed, solved, time_s, stats {…}, and for solved runs path_length_m,
   path_vertices and primitives {transit, push, pickup, transfer}. */
#pragma once

#include "ompl_mm/geometric/ManipulationSetup.h"

#include <ostream>
#include <string>

namespace ompl_mm
{
    /** What a run was asked to do. */
    struct RunDescription
    {
        std::string scene;      ///< scene name
        std::string planner;    ///< planner name
        unsigned long seed{0};  ///< random seed
        double timeLimit{0.0};  ///< seconds
    };

    /** Writes the result of the setup's last solve() as one JSON object. */
    void writeResultJson(std::ostream &out, const RunDescription &run, const ManipulationSetup &setup);
}  // namespace ompl_mm
