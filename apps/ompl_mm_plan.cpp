// ompl_mm_plan: plans a manipulation scene with MOPL and reports the result.
// Exit codes: 0 solved, 1 not solved, 2 bad input.
#include "common/AppSupport.h"
#include "common/KeepUntilExit.h"
#include "common/RunTermination.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/PhaseTimes.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/io/PlanningRun.h"
#include "ompl_mm/io/SceneHtml.h"
#include "ompl_mm/io/SceneSvg.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"
#include "ompl_mm/setup/MoplRace.h"
#include "ompl_mmphys/io/PhysicsCheckRecord.h"
#include "ompl_mmphys/primitives/PhysicsPrimitives.h"

#include <ompl/util/Console.h>

#include <boost/program_options.hpp>

#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace po = boost::program_options;

namespace
{
    struct Options
    {
        apps::CommonOptions common{"mopl"};
        std::string path;       ///< path file, empty for none
        bool simulate{false};   ///< check the plan in physics
        std::string pushModel;  ///< the model every push primitive takes, empty: the scene's
        long long threads{1};   ///< MOPL searches racing (signed, so that a negative count is caught)
    };

    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description extra;
        extra.add_options()("path", po::value(&options.path), "write the path's waypoints to this text file")(
            "simulate", po::bool_switch(&options.simulate),
            "execute the plan in physics (ODE): report whether the objects end where planned (JSON: "
            "physics_check; --path: the simulated poses as columns sim.OBJECT.x ...; --html: the "
            "simulated objects, translucent, beside the planned ones)")(
            "push-model", po::value(&options.pushModel),
            "give every push primitive of the scene this model: kinematic, or physics (each push "
            "simulated in ODE while planning)")(
            "threads", po::value(&options.threads)->default_value(options.threads)->value_name("N"),
            "MOPL searches racing, one thread each (1 to 64): the one that solves in the fewest "
            "iterations wins, so a seed and N give the same plan whatever the timing");
        if (!apps::parseCommandLine(
                argc, argv,
                "Usage: ompl_mm_plan SCENE.xml [options]\n"
                "Plans a multi-modal manipulation task (transit, push, pickup, transfer) with MOPL, or a "
                "task\n"
                "without manipulation with one of OMPL's planners as well.\n",
                "planner to use (" + ompl_mm::ManipulationSetup::plannerRegistry().nameList() + ")", extra,
                options.common, exitCode))
            return false;
        ompl_mm::ManipulationSetup::plannerRegistry().require(options.common.planner);
        if (options.threads < 1 || options.threads > ompl_mm::MoplRace::MAX_SEARCHES)
            throw ompl_core::InputError("--threads must be 1 to " +
                                        std::to_string(ompl_mm::MoplRace::MAX_SEARCHES) + ", got " +
                                        std::to_string(options.threads));
        return true;
    }

    void printSummary(const ompl_mm::Scene &scene, const ompl_mm::PlanningRun &run, const Options &options)
    {
        const ompl_mm::ManipulationSetup &setup = run.setup();
        const bool solved = run.solved();
        const double time = run.planningTime();
        std::cout << std::fixed << std::setprecision(3) << "scene " << scene.name << ": "
                  << (solved ? "solved" : "not solved") << " in " << time << " s (planner "
                  << options.common.planner << ", seed " << options.common.seed << ")\n";
        if (solved)
        {
            const ompl_mm::ManipulationPath &path = setup.manipulationPath();
            std::cout << std::setprecision(2) << "  path: " << path.getStateCount()
                      << " waypoints, tool path " << path.toolPathLength() << " m;";
            for (const auto &[kind, count] : path.primitiveCounts())
                if (count > 0)
                    std::cout << ' ' << count << ' ' << kind;
            std::cout << '\n';
        }
        if (!setup.mopl())
            return;  // MOPL's statistics; another planner's are in its planner data (--json)
        const ompl_mm::MOPLStatistics &stats = setup.mopl()->statistics();
        // shares of the search's own time (a race's winner planned for part of the race)
        const double own = setup.getLastPlanComputationTime();
        const double share = own > 0.0 ? 100.0 / own : 0.0;
        std::cout << std::setprecision(1) << "  search: " << stats.iterations << " iterations, "
                  << stats.restarts << " restarts, " << stats.collisionQueries
                  << " collision queries; time in nearest neighbour " << stats.nearestTime * share
                  << " %, propagate " << stats.propagateTime * share << " %, connect "
                  << stats.connectTime * share << " %\n";
        // what kept the primitives from acting, when nothing solved
        std::istringstream never(solved ? std::string() : setup.mopl()->primitiveTally().failureSummary());
        for (std::string line; std::getline(never, line);)
            std::cout << "  never succeeded: " << line << "\n";
    }

    /** Executes the solution in physics, adds the check to the run's record, prints and returns it. */
    ompl_mmphys::PhysicsCheck checkInPhysics(ompl_mm::PlanningRun &run)
    {
        const ompl_mmphys::PhysicsCheck check =
            ompl_mmphys::checkPlan(run.setup(), run.setup().manipulationPath());
        run.addRecord("physics_check", ompl_mmphys::physicsCheckRecord(check));
        std::cout << std::setprecision(3)
                  << "  physics: " << (check.confirmed ? "confirmed" : "not confirmed")
                  << "; largest end error " << check.maxPositionError << " m";
        for (const ompl_mmphys::ObjectCheck &object : check.objects)
            if (object.positionError == check.maxPositionError && check.maxPositionError > 0.0)
                std::cout << " (" << object.name << ")";
        std::cout << ", goal " << (check.goalHolds ? "holds" : "does not hold") << "; "
                  << std::setprecision(1) << check.simulatedSeconds << " s simulated in "
                  << std::setprecision(2) << check.wallSeconds << " s\n";
        return check;
    }

    int run(const Options &options)
    {
        ompl_core::PhaseTimes loading;
        ompl_mm::Scene scene = ompl_mm::loadScene(options.common.scene);
        if (!options.pushModel.empty())
            scene.setPushModel(options.pushModel);
        auto request = options.common.request<ompl_mm::PlanningRequest>();
        request.threads = static_cast<unsigned int>(options.threads);
        ompl_mm::PlanningRun &run = apps::keepUntilExit(std::make_unique<ompl_mm::PlanningRun>(
            scene, request, loading.lap(), ompl_mmphys::physicsPrimitiveFactory()));
        if (options.common.listParams)
        {
            options.common.printParameters(*run.setup().getPlanner());
            return 0;
        }
        // open the outputs first: a bad path should not cost a whole planning run
        ompl_core::OutputFile json(options.common.json);
        ompl_core::OutputFile svg(options.common.svg);
        ompl_core::OutputFile html(options.common.html);
        ompl_core::OutputFile path(options.path);
        run.solve(apps::interruptCondition());

        // the checks: the run's re-check of the path, the summary, the files; the JSON last, so
        // that its "checks" phase holds all of them but its own writing
        const bool solved = run.solved();
        const ompl_mm::ManipulationSetup &setup = run.setup();  // a race's winner
        printSummary(scene, run, options);
        std::optional<ompl_mmphys::PhysicsCheck> check;
        if (options.simulate && solved)
            check = checkInPhysics(run);
        if (svg.isOpen())
        {
            ompl_mm::writeSceneSvg(svg.stream(), setup, solved ? &setup.manipulationPath() : nullptr);
            svg.commit();
        }
        if (html.isOpen())
        {
            const std::optional<ompl_mm::CompanionPoses> simulated =
                check ? std::optional(ompl_mmphys::simulatedCompanions(*check)) : std::nullopt;
            ompl_mm::writeSceneHtml(html.stream(), setup, solved ? &setup.manipulationPath() : nullptr,
                                    scene.name + " · " + options.common.planner + " · seed " +
                                        std::to_string(options.common.seed),
                                    simulated ? &*simulated : nullptr);
            html.commit();
        }
        if (path.isOpen())
        {
            if (solved)  // without a solution the file stays empty
                ompl_mm::writePathFile(
                    path.stream(), setup.manipulationPath(),
                    check ? ompl_mmphys::simulatedPoseColumns(*check) : ompl_mm::ExtraColumns());
            path.commit();
        }
        return apps::finishRun(run, json, options.common.verbose);
    }
}  // namespace

int main(int argc, char **argv)
{
    return apps::runApp<Options>(
        "ompl_mm_plan",
        [&](Options &options, int &exitCode) { return parseOptions(argc, argv, options, exitCode); }, run);
}
