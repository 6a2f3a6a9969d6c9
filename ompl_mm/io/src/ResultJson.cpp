#include "ompl_mm/io/ResultJson.h"

#include "ompl_mm/io/TextFormat.h"

#include <iomanip>

namespace ompl_mm
{
    namespace
    {
        void writeStats(std::ostream &out, const MOPLStatistics &s)
        {
            out << "  \"stats\": {\n"
                << "    \"time_sampling_s\": " << s.samplingTime << ",\n"
                << "    \"time_nearest_s\": " << s.nearestTime << ",\n"
                << "    \"time_propagate_s\": " << s.propagateTime << ",\n"
                << "    \"time_connect_s\": " << s.connectTime << ",\n"
                << "    \"time_smoothing_s\": " << s.smoothingTime << ",\n"
                << "    \"time_ik_s\": 0,\n"
                << "    \"iterations\": " << s.iterations << ",\n"
                << "    \"restarts\": " << s.restarts << ",\n"
                << "    \"collision_queries\": " << s.collisionQueries << ",\n"
                << "    \"collision_queries_free\": " << s.freeCollisionQueries << "\n"
                << "  }";
        }
    }  // namespace

    void writeResultJson(std::ostream &out, const RunDescription &run, const ManipulationSetup &setup)
    {
        const bool solved = setup.getProblemDefinition()->hasExactSolution();
        const MOPL &planner = *setup.mopl();
        ompl::base::PlannerData data(setup.getSpaceInformation());
        planner.getPlannerData(data);
        writeRunHeader(out, run, solved, setup.getLastPlannerStatus().asString(),
                       setup.getLastPlanComputationTime());
        out << "  \"tree_vertices\": " << data.numVertices() << ",\n"
            << "  \"tree_edges\": " << data.numEdges() << ",\n";
        writeStats(out, planner.statistics());
        if (solved)
        {
            const ManipulationPath &path = setup.manipulationPath();
            out << ",\n  \"path_length_m\": " << path.toolPathLength() << ",\n"
                << "  \"path_vertices\": " << path.getStateCount() << ",\n"
                << "  \"primitives\": {";
            bool first = true;
            for (const auto &[kind, count] : path.primitiveCounts())
            {
                out << (first ? "" : ", ") << jsonQuoted(kind) << ": " << count;
                first = false;
            }
            out << "}";
        }
        out << "\n}\n";
    }
}  // namespace ompl_mm
