// ompl_phys_plan: plans a physics scene (pushing with ODE) with an OMPL control planner,
// re-simulates the solution from its controls and reports the result.
// Exit codes: 0 solved, 1 not solved, 2 bad input.
#include "common/AppSupport.h"
#include "common/KeepUntilExit.h"
#include "common/RunTermination.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/PhaseTimes.h"
#include "ompl_phys/control/PathSimulation.h"
#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/io/PhysicsPathFile.h"
#include "ompl_phys/io/PhysicsPlanningRun.h"
#include "ompl_phys/io/PhysicsSceneHtml.h"
#include "ompl_phys/io/PhysicsSceneSvg.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <iomanip>
#include <iostream>

namespace po = boost::program_options;

namespace
{
    struct Options
    {
        apps::CommonOptions common{"kpiece"};
        std::string path;  ///< re-simulated path file, empty for none
    };

    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description extra;
        extra.add_options()("path", po::value(&options.path),
                            "write the re-simulated solution (forces, robot and body positions per step) to "
                            "this text file");
        if (!apps::parseCommandLine(
                argc, argv,
                "Usage: ompl_phys_plan SCENE.xml [options]\n"
                "Plans a physics-based pushing task: a sphere robot driven by a planar force in an ODE\n"
                "world, with manipulation knowledge, using an OMPL control planner.\n",
                "control planner: " + ompl_phys::PhysicsSetup::plannerRegistry().nameList(), extra,
                options.common, exitCode))
            return false;
        ompl_phys::PhysicsSetup::plannerRegistry().require(options.common.planner);
        return true;
    }

    void printSummary(const ompl_phys::PhysicsSetup &setup, const Options &options,
                      const ompl_phys::SimulatedPath *simulated)
    {
        const bool solved = setup.haveExactSolution();
        const auto &counters = setup.propagator().counters();
        std::cout << std::fixed << std::setprecision(3) << "scene " << setup.scene().name << ": "
                  << (solved ? "solved" : "not solved") << " in " << setup.getLastPlanComputationTime()
                  << " s (planner " << options.common.planner << ", seed " << options.common.seed << ")\n";
        const auto occupants = setup.knowledge().goalOccupants(setup.world().startStates());
        for (std::size_t body : occupants)
            std::cout << "  goal occupied by " << setup.world().movingBodyName(body) << " at the start\n";
        if (simulated)
        {
            const ompl_phys::TrajectoryMetrics &m = simulated->metrics;
            std::cout << "  path: " << simulated->robot.moves.size() << " moves, "
                      << simulated->robot.stepDuration *
                             static_cast<double>(simulated->robot.positions.size() - 1)
                      << " s; re-simulated: "
                      << (simulated->reachesGoal ? "reaches the goal" : "does NOT reach the goal")
                      << "\n  action " << m.action << " N s m, power " << m.power << " W, smoothness "
                      << m.smoothness << " m^2/s^5\n";
        }
        std::cout << "  search: " << counters.propagations << " propagations, " << counters.substeps
                  << " ODE steps\n";
    }

    int run(const Options &options)
    {
        ompl_core::PhaseTimes loading;
        const ompl_phys::PhysicsScene scene = ompl_phys::loadPhysicsScene(options.common.scene);
        const auto request = options.common.request<ompl_phys::PhysicsPlanningRequest>();
        ompl_phys::PhysicsPlanningRun &run = apps::keepUntilExit(
            std::make_unique<ompl_phys::PhysicsPlanningRun>(scene, request, loading.lap()));
        ompl_phys::PhysicsSetup &setup = run.setup();
        if (options.common.listParams)
        {
            options.common.printParameters(*setup.getPlanner());
            return 0;
        }
        // open the outputs first: a bad path should not cost a whole planning run
        ompl_core::OutputFile json(options.common.json);
        ompl_core::OutputFile svg(options.common.svg);
        ompl_core::OutputFile html(options.common.html);
        ompl_core::OutputFile path(options.path);
        run.solve(apps::interruptCondition());

        // the checks: the run's re-simulation of the solution, the summary, the files; the JSON
        // last, so that its "checks" phase holds all of them but its own writing
        const ompl_phys::SimulatedPath *result = run.simulated();
        printSummary(setup, options, result);
        const std::string title =
            scene.name + " · " + options.common.planner + " · seed " + std::to_string(options.common.seed);
        if (svg.isOpen())
        {
            ompl_phys::writePhysicsSceneSvg(svg.stream(), setup, result, title);
            svg.commit();
        }
        if (html.isOpen())
        {
            ompl_phys::writePhysicsSceneHtml(html.stream(), setup, result, title);
            html.commit();
        }
        if (path.isOpen())
        {
            if (result)  // without a solution the file stays empty
                ompl_phys::writeSimulatedPathFile(path.stream(), setup, *result);
            path.commit();
        }
        return apps::finishRun(run, json, options.common.verbose);
    }
}  // namespace

int main(int argc, char **argv)
{
    return apps::runApp<Options>(
        "ompl_phys_plan",
        [&](Options &options, int &exitCode) { return parseOptions(argc, argv, options, exitCode); }, run);
}
