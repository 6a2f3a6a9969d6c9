// ompl_mm_plan: plans a manipulation scene with MOPL and reports the result.
// Exit codes: 0 solved, 1 not solved, 2 bad input.
#include "common/AppSupport.h"
#include "common/KeepUntilExit.h"
#include "common/PhaseTimes.h"
#include "common/RunTermination.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/GlobalSeed.h"
#include "ompl_mm/base/StepTermination.h"
#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/io/ManipulationRunResult.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/io/SceneHtml.h"
#include "ompl_mm/io/SceneSvg.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

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
        std::string path;  ///< path file, empty for none
    };

    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description extra;
        extra.add_options()("path", po::value(&options.path), "write the path's waypoints to this text file");
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
        return true;
    }

    void printSummary(const ompl_mm::Scene &scene, const ompl_mm::ManipulationSetup &setup,
                      const Options &options)
    {
        const bool solved = setup.getProblemDefinition()->hasExactSolution();
        const double time = setup.getLastPlanComputationTime();
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
        const double share = time > 0.0 ? 100.0 / time : 0.0;
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

    /** Solves within termination, whatever the planner: MOPL polls it within every step, and
        the motion validator's checks stop at it too (OMPL's planners call checkMotion between
        their polls, and one continuous check near triangle meshes can take a tenth of a second).
        Here, not in ManipulationSetup::solve: the app's condition is a time limit, while a library
        user's may count its evaluations (OMPL's IterationTerminationCondition), which the checks'
        polls would use up. */
    void solveWithin(ompl_mm::ManipulationSetup &setup,
                     const ompl::base::PlannerTerminationCondition &termination)
    {
        const ompl_mm::StepTermination inner(termination);
        std::optional<ompl_mm::ManipulationMotionValidator::TerminationScope> bounded;
        if (auto validator = std::dynamic_pointer_cast<ompl_mm::ManipulationMotionValidator>(
                setup.getSpaceInformation()->getMotionValidator()))
            bounded.emplace(*validator, inner.condition());
        setup.solve(termination);
    }

    int run(const Options &options)
    {
        apps::PhaseTimes phases;
        const ompl_mm::Scene scene = ompl_mm::loadScene(options.common.scene);
        phases.load = phases.lap();
        ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(options.common.seed));
        ompl_mm::ManipulationSetup &setup =
            apps::keepUntilExit(std::make_unique<ompl_mm::ManipulationSetup>(scene));
        if (setup.goalFault())  // the scene is the app's input: an impossible goal is an input error
            throw *setup.goalFault();
        if (options.common.planner != scene.planner)
            setup.selectPlanner(options.common.planner);
        setup.applyParameters(options.common.parameterSettings());
        if (options.common.listParams)
        {
            options.common.printParameters(*setup.getPlanner());
            return 0;
        }
        if (const std::shared_ptr<ompl_mm::MOPL> mopl = setup.mopl())
            mopl->setSeed(static_cast<std::uint_fast32_t>(options.common.seed));
        // open the outputs first: a bad path should not cost a whole planning run
        ompl_core::OutputFile json(options.common.json);
        ompl_core::OutputFile svg(options.common.svg);
        ompl_core::OutputFile html(options.common.html);
        ompl_core::OutputFile path(options.path);

        const double timeLimit = options.common.timeLimit > 0.0 ? options.common.timeLimit : scene.timeLimit;
        setup.setup();
        ompl_core::reseedOmpl(static_cast<std::uint32_t>(options.common.seed));  // as the benchmark tool does
        phases.setup = phases.lap();
        solveWithin(setup, apps::runTermination(timeLimit));
        phases.solve = phases.lap();

        // the checks: one re-check of the path (the JSON reports the same), the summary, the files;
        // the JSON last, so that its "checks" phase holds all of them but its own writing
        const bool solved = setup.getProblemDefinition()->hasExactSolution();
        const bool pathValid = solved && setup.manipulationPath().check();
        if (solved && !pathValid)
            OMPL_ERROR("ompl_mm_plan: the solution failed OMPL's path re-check");
        printSummary(scene, setup, options);
        if (svg.isOpen())
        {
            ompl_mm::writeSceneSvg(svg.stream(), setup, solved ? &setup.manipulationPath() : nullptr);
            svg.commit();
        }
        if (html.isOpen())
        {
            ompl_mm::writeSceneHtml(html.stream(), setup, solved ? &setup.manipulationPath() : nullptr,
                                    scene.name + " · " + options.common.planner + " · seed " +
                                        std::to_string(options.common.seed));
            html.commit();
        }
        if (path.isOpen())
        {
            if (solved)  // without a solution the file stays empty
                ompl_mm::writePathFile(path.stream(), setup.manipulationPath());
            path.commit();
        }
        if (json.isOpen())
        {
            ompl_core::RunResult result =
                ompl_mm::manipulationRunResult(options.common.describe(scene.name, timeLimit), setup,
                                               solved ? std::optional<bool>(pathValid) : std::nullopt);
            phases.checks = phases.sinceLap();
            result.details.addRecord("phases_s", phases.record());
            ompl_core::writeRunJson(json.stream(), result);
            json.commit();
        }
        phases.checks = phases.lap();
        if (options.common.verbose)
            phases.print(std::cout);
        return solved ? 0 : 1;
    }
}  // namespace

int main(int argc, char **argv)
{
    return apps::runApp<Options>(
        "ompl_mm_plan",
        [&](Options &options, int &exitCode) { return parseOptions(argc, argv, options, exitCode); }, run);
}
