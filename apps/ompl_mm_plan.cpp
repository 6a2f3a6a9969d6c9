// ompl_mm_plan: plans a manipulation scene with MOPL and reports the result.
// Exit codes: 0 solved, 1 not solved, 2 bad input.
#include "common/AppSupport.h"
#include "ompl_mm/geometric/ManipulationSetup.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/io/ResultJson.h"
#include "ompl_mm/io/SceneSvg.h"
#include "ompl_mm/scene/SceneLoader.h"

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <boost/program_options.hpp>

#include <fstream>
#include <iomanip>
#include <iostream>

namespace po = boost::program_options;

namespace
{
    struct Options
    {
        std::string scene;
        std::string planner{"mopl"};
        long long seed{1};       ///< checked to be in [1, 2^32 - 1]
        double timeLimit{-1.0};  ///< negative: the scene's
        std::string json, svg, path;
        bool verbose{false};
    };

    /** Parses the command line; returns false when the program should exit with `exitCode`. */
    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description named("Options");
        named.add_options()("help,h", "print this help and exit")(
            "planner", po::value(&options.planner)->default_value("mopl"), "planner to use (mopl)")(
            "seed", po::value(&options.seed)->default_value(1), "random seed (positive)")(
            "time-limit", po::value(&options.timeLimit),
            "planning time limit in seconds (default: the scene's)")("json", po::value(&options.json),
                                                                     "write the result as JSON to this file")(
            "svg", po::value(&options.svg), "write a top-down picture of the plan to this SVG file")(
            "path", po::value(&options.path), "write the path's waypoints to this text file")(
            "verbose,v", po::bool_switch(&options.verbose), "print OMPL's informational messages");
        po::options_description hidden;
        hidden.add_options()("scene", po::value(&options.scene));
        po::options_description all;
        all.add(named).add(hidden);
        po::positional_options_description positional;
        positional.add("scene", 1);

        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
        po::notify(vm);
        if (vm.count("help") || options.scene.empty())
        {
            std::cout << "Usage: ompl_mm_plan SCENE.xml [options]\n"
                      << "Plans a multi-modal manipulation task (transit, push, ...) with MOPL.\n"
                      << "Exit status: 0 solved, 1 not solved, 2 bad input.\n\n"
                      << named;
            exitCode = vm.count("help") ? 0 : 2;
            return false;
        }
        if (options.planner != "mopl")
            throw ompl_mm::InputError("unknown planner '" + options.planner + "' (known: mopl)");
        ompl_mm::apps::checkSeedAndTimeLimit(options.seed, vm.count("time-limit") > 0, options.timeLimit);
        return true;
    }

    void printSummary(const ompl_mm::Scene &scene, const ompl_mm::ManipulationSetup &setup,
                      const Options &options)
    {
        const bool solved = setup.getProblemDefinition()->hasExactSolution();
        const double time = setup.getLastPlanComputationTime();
        const ompl_mm::MOPLStatistics &stats = setup.mopl()->statistics();
        std::cout << std::fixed << std::setprecision(3) << "scene " << scene.name << ": "
                  << (solved ? "solved" : "not solved") << " in " << time << " s (planner " << options.planner
                  << ", seed " << options.seed << ")\n";
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
        const double share = time > 0.0 ? 100.0 / time : 0.0;
        std::cout << std::setprecision(1) << "  search: " << stats.iterations << " iterations, "
                  << stats.restarts << " restarts, " << stats.collisionQueries
                  << " collision queries; time in nearest neighbour " << stats.nearestTime * share
                  << " %, propagate " << stats.propagateTime * share << " %, connect "
                  << stats.connectTime * share << " %\n";
    }

    int run(const Options &options)
    {
        const ompl_mm::Scene scene = ompl_mm::loadScene(options.scene);
        ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(options.seed));
        ompl_mm::ManipulationSetup setup(scene);
        setup.mopl()->setSeed(static_cast<std::uint_fast32_t>(options.seed));
        // open the outputs first: a bad path should not cost a whole planning run
        std::ofstream json = ompl_mm::apps::openOutput(options.json);
        std::ofstream svg = ompl_mm::apps::openOutput(options.svg);
        std::ofstream path = ompl_mm::apps::openOutput(options.path);

        const double timeLimit = options.timeLimit > 0.0 ? options.timeLimit : scene.timeLimit;
        setup.solve(timeLimit);
        const bool solved = setup.getProblemDefinition()->hasExactSolution();
        if (solved && !setup.manipulationPath().check())
            OMPL_ERROR("ompl_mm_plan: the solution failed OMPL's path re-check");

        printSummary(scene, setup, options);
        if (json.is_open())
            ompl_mm::writeResultJson(
                json, {scene.name, options.planner, static_cast<unsigned long>(options.seed), timeLimit},
                setup);
        if (svg.is_open())
            ompl_mm::writeSceneSvg(svg, setup, solved ? &setup.manipulationPath() : nullptr);
        if (path.is_open() && solved)
            ompl_mm::writePathFile(path, setup.manipulationPath());
        return solved ? 0 : 1;
    }
}  // namespace

int main(int argc, char **argv)
{
    return ompl_mm::apps::runApp(
        "ompl_mm_plan",
        [&]
        {
            Options options;
            int exitCode = 0;
            if (!parseOptions(argc, argv, options, exitCode))
                return exitCode;
            ompl::msg::setLogLevel(options.verbose ? ompl::msg::LOG_INFO : ompl::msg::LOG_WARN);
            return run(options);
        });
}
