#include "ompl_phys/io/PhysicsRunResult.h"

#include "ompl_phys/control/PDSTPlanner.h"

#include <ompl/control/PlannerData.h>

namespace ompl_phys
{
    namespace
    {
        std::size_t treeVertexCount(const PhysicsSetup &setup)
        {
            if (const auto *pdst = dynamic_cast<const PDSTPlanner *>(setup.getPlanner().get()))
                return pdst->motionCount();
            ompl::control::PlannerData data(setup.getSpaceInformation());
            setup.getPlanner()->getPlannerData(data);
            return data.numVertices();
        }

        ompl_core::RunRecord statisticsRecord(const PhysicsSetup &setup)
        {
            // a copy: reading the tree may propagate, which must not count as planning
            const PhysicsStatePropagator::Counters c = setup.propagator().counters();
            ompl_core::RunRecord stops;
            for (int v = 1; v < VIOLATION_KINDS; ++v)
                stops.addCount(violationName(static_cast<Violation>(v)),
                               c.stops[static_cast<std::size_t>(v)]);
            ompl_core::RunRecord stats;
            stats.addCount("propagations", c.propagations)
                .addCount("substeps", c.substeps)
                .addCount("tree_vertices", treeVertexCount(setup))
                .addRecord("stops", stops);
            return stats;
        }
    }  // namespace

    ompl_core::RunResult physicsRunResult(const ompl_core::RunDescription &run, const PhysicsSetup &setup,
                                          const SimulatedPath *simulated)
    {
        ompl_core::RunResult result =
            ompl_core::runResult(run, *setup.getProblemDefinition(), setup.getLastPlannerStatus(),
                                 setup.getLastPlanComputationTime());
        std::vector<std::string> occupants;
        for (std::size_t body : setup.knowledge().goalOccupants(setup.world().startStates()))
            occupants.push_back(setup.world().movingBodyName(body));
        result.details.addTexts("goal_occupied_by", occupants).addRecord("stats", statisticsRecord(setup));
        if (result.solved && simulated)
        {
            const TrajectoryMetrics &metrics = simulated->metrics;
            const std::size_t steps = simulated->robot.positions.size() - 1;
            result.details.addFlag("reaches_goal", simulated->reachesGoal)
                .addText("violation", violationName(simulated->violation))
                .addCount("moves", simulated->robot.moves.size())
                .addCount("steps", steps)
                .addNumber("duration_s", static_cast<double>(steps) * simulated->robot.stepDuration)
                .addNumber("action", metrics.action)
                .addNumber("power", metrics.power)
                .addNumber("smoothness", metrics.smoothness);
        }
        return result;
    }
}  // namespace ompl_phys
