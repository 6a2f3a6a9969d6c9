#include "ompl_mm/io/ManipulationRunResult.h"

#include <ompl/base/PlannerData.h>

namespace ompl_mm
{
    namespace
    {
        ompl_core::RunRecord statisticsRecord(const MOPLStatistics &s)
        {
            ompl_core::RunRecord stats;
            stats.addNumber("time_sampling_s", s.samplingTime)
                .addNumber("time_nearest_s", s.nearestTime)
                .addNumber("time_propagate_s", s.propagateTime)
                .addNumber("time_connect_s", s.connectTime)
                .addNumber("time_smoothing_s", s.smoothingTime)
                .addNumber("time_ik_s", s.ikTime)
                .addCount("iterations", s.iterations)
                .addCount("restarts", s.restarts)
                .addCount("clearings", s.clearings)
                .addCount("collision_queries", s.collisionQueries)
                .addCount("collision_queries_free", s.freeCollisionQueries);
            return stats;
        }
    }  // namespace

    ompl_core::RunResult manipulationRunResult(const ompl_core::RunDescription &run,
                                               const ManipulationSetup &setup)
    {
        ompl_core::RunResult result =
            ompl_core::runResult(run, *setup.getProblemDefinition(), setup.getLastPlannerStatus(),
                                 setup.getLastPlanComputationTime());
        ompl::base::PlannerData data(setup.getSpaceInformation());
        setup.getPlanner()->getPlannerData(data);
        result.details.addCount("tree_vertices", data.numVertices()).addCount("tree_edges", data.numEdges());
        // MOPL's statistics; another registered planner has only its planner data
        if (const std::shared_ptr<MOPL> mopl = setup.mopl())
            result.details.addRecord("stats", statisticsRecord(mopl->statistics()));
        if (result.solved)
        {
            const ManipulationPath &path = setup.manipulationPath();
            ompl_core::RunRecord primitives;
            for (const auto &[kind, count] : path.primitiveCounts())
                primitives.addCount(kind, count);
            result.details.addNumber("path_length_m", path.toolPathLength())
                .addCount("path_vertices", path.getStateCount())
                .addFlag("path_valid", path.check())  // OMPL's own re-check of states and motions
                .addRecord("primitives", primitives);
        }
        return result;
    }
}  // namespace ompl_mm
