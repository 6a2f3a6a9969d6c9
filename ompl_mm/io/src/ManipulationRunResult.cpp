#include "ompl_mm/io/ManipulationRunResult.h"

#include <ompl/base/PlannerData.h>

#include <algorithm>
#include <utility>
#include <vector>

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

        /** Per primitive kind: attempts, motions found and checked, and why they failed, most
            frequent first ("1180: motion stopped by robot link 'hand' and object 'cyl1'"). */
        ompl_core::RunRecord tallyRecord(const PrimitiveTally &tally)
        {
            ompl_core::RunRecord kinds;
            for (const auto &[kind, record] : tally.records())
            {
                std::vector<std::pair<std::uint64_t, std::string>> reasons;
                for (const auto &[reason, count] : record.reasons)
                    reasons.emplace_back(count, reason);
                std::stable_sort(reasons.begin(), reasons.end(),
                                 [](const auto &a, const auto &b) { return a.first > b.first; });
                std::vector<std::string> texts;
                for (const auto &[count, reason] : reasons)
                    texts.push_back(std::to_string(count) + ": " + reason);
                ompl_core::RunRecord entry;
                entry.addCount("attempts", record.attempts)
                    .addCount("no_motion", record.noMotion)
                    .addCount("motions_checked", record.motions)
                    .addCount("motions_stopped", record.stopped)
                    .addCount("motions_completed", record.completed)
                    .addFlag("never_succeeded", record.neverSucceeded())
                    .addTexts("reasons", texts);
                kinds.addRecord(kind, entry);
            }
            return kinds;
        }
    }  // namespace

    ompl_core::RunResult manipulationRunResult(const ompl_core::RunDescription &run,
                                               const ManipulationSetup &setup, std::optional<bool> pathValid)
    {
        ompl_core::RunResult result =
            ompl_core::runResult(run, *setup.getProblemDefinition(), setup.getLastPlannerStatus(),
                                 setup.getLastPlanComputationTime());
        ompl::base::PlannerData data(setup.getSpaceInformation());
        setup.getPlanner()->getPlannerData(data);
        result.details.addCount("tree_vertices", data.numVertices()).addCount("tree_edges", data.numEdges());
        // MOPL's statistics; another registered planner has only its planner data
        if (const std::shared_ptr<MOPL> mopl = setup.mopl())
            result.details.addRecord("stats", statisticsRecord(mopl->statistics()))
                .addRecord("primitive_attempts", tallyRecord(mopl->primitiveTally()));
        if (result.solved)
        {
            const ManipulationPath &path = setup.manipulationPath();
            ompl_core::RunRecord primitives;
            for (const auto &[kind, count] : path.primitiveCounts())
                primitives.addCount(kind, count);
            result.details.addNumber("path_length_m", path.toolPathLength())
                .addCount("path_vertices", path.getStateCount())
                // OMPL's own re-check of states and motions
                .addFlag("path_valid", pathValid ? *pathValid : path.check())
                .addCount("push_reversals", path.pushReversals().size())
                .addRecord("primitives", primitives);
        }
        return result;
    }
}  // namespace ompl_mm
