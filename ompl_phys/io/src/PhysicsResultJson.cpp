#include "ompl_phys/io/PhysicsResultJson.h"

#include "ompl_mm/io/TextFormat.h"

#include <ompl/control/PlannerData.h>

#include <iomanip>

namespace ompl_phys
{
    using ompl_mm::jsonQuoted;

    namespace
    {
        void writeStats(std::ostream &out, const PhysicsSetup &setup)
        {
            const PhysicsStatePropagator::Counters &c = setup.propagator().counters();
            ompl::control::PlannerData data(setup.getSpaceInformation());
            setup.getPlanner()->getPlannerData(data);
            out << "  \"stats\": {\n"
                << "    \"propagations\": " << c.propagations << ",\n"
                << "    \"substeps\": " << c.substeps << ",\n"
                << "    \"tree_vertices\": " << data.numVertices() << ",\n"
                << "    \"stops\": {";
            for (int v = 1; v < VIOLATION_KINDS; ++v)
                out << (v == 1 ? "" : ", ") << jsonQuoted(violationName(static_cast<Violation>(v))) << ": "
                    << c.stops[static_cast<std::size_t>(v)];
            out << "}\n  }";
        }
    }  // namespace

    void writePhysicsResultJson(std::ostream &out, const ompl_mm::RunDescription &run,
                                const PhysicsSetup &setup, const SimulatedPath *simulated)
    {
        const bool solved = setup.haveExactSolution();
        ompl_mm::writeRunHeader(out, run, solved, setup.getLastPlannerStatus().asString(),
                                setup.getLastPlanComputationTime());
        out << "  \"goal_occupied_by\": [";
        const std::vector<std::size_t> occupants =
            setup.knowledge().goalOccupants(setup.world().startStates());
        for (std::size_t i = 0; i < occupants.size(); ++i)
            out << (i ? ", " : "") << jsonQuoted(setup.world().movingBodyName(occupants[i]));
        out << "],\n";
        writeStats(out, setup);
        if (solved && simulated)
        {
            const TrajectoryMetrics &metrics = simulated->metrics;
            out << ",\n  \"reaches_goal\": " << (simulated->reachesGoal ? "true" : "false") << ",\n"
                << "  \"violation\": " << jsonQuoted(violationName(simulated->violation)) << ",\n"
                << "  \"moves\": " << simulated->robot.moves.size() << ",\n"
                << "  \"steps\": " << simulated->robot.positions.size() - 1 << ",\n"
                << "  \"duration_s\": "
                << static_cast<double>(simulated->robot.positions.size() - 1) * simulated->robot.stepDuration
                << ",\n"
                << "  \"action\": " << metrics.action << ",\n"
                << "  \"power\": " << metrics.power << ",\n"
                << "  \"smoothness\": " << metrics.smoothness;
        }
        out << "\n}\n";
    }
}  // namespace ompl_phys
