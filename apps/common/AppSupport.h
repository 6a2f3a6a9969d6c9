/* What the command-line apps share: the common options (scene, --planner, --seed, --time-limit,
   --param, --list-params, --json, --svg, --verbose) with their checks, the run description, and the
   mapping of failures to exit codes (2 for bad input, 1 for an output file that could not be written,
   with the message on stderr prefixed by the app's name). */
#pragma once

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/io/PlanViewer.h"
#include "ompl_core/run/CommandLine.h"
#include "ompl_core/run/ExitStatus.h"
#include "ompl_core/run/ParameterSetting.h"
#include "ompl_core/run/RunRecord.h"

#include <ompl/util/Console.h>

#include <boost/program_options.hpp>

#include <cstdint>

#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace apps
{
    /** The options every planning app has. */
    struct CommonOptions
    {
        explicit CommonOptions(std::string defaultPlanner) : planner(std::move(defaultPlanner)) {}

        std::string scene;
        std::string planner;
        long long seed{1};                ///< checked to be in [1, 2^32 - 1]
        double timeLimit{-1.0};           ///< seconds; negative: the scene's
        std::vector<std::string> params;  ///< NAME=VALUE, applied after the scene's parameters
        std::string json, svg, html;
        bool verbose{false};
        bool listParams{false};  ///< print the planner's parameters instead of planning

        /** Prints the planner's declared parameters, their values for this run and their ranges. */
        static void printParameters(const ompl::base::Planner &planner)
        {
            std::cout << "parameters of " << planner.getName() << " (set with --param NAME=VALUE):\n";
            for (const std::string &line : ompl_core::describeParameters(planner))
                std::cout << "  " << line << '\n';
        }

        /** The --param settings. @throws ompl_core::InputError for one without NAME=. */
        std::vector<ompl_core::ParameterSetting> parameterSettings() const
        {
            std::vector<ompl_core::ParameterSetting> settings;
            for (const std::string &param : params)
                settings.push_back(ompl_core::parseParameterOption(param));
            return settings;
        }

        /** The planning run's Request (ompl_mm::PlanningRequest, ompl_phys::PhysicsPlanningRequest):
            planner, seed, time limit (negative: the scene's) and the --param settings.
            @throws ompl_core::InputError for a --param without NAME=. */
        template <typename Request>
        Request request() const
        {
            Request request;
            request.planner = planner;
            request.seed = static_cast<std::uint32_t>(seed);
            request.timeLimit = timeLimit;
            request.parameters = parameterSettings();
            return request;
        }
    };

    /** Ends a planning run's outputs: its record to json (when open), the "checks" phase, and the
        phases printed with verbose. Returns the exit code: 0 solved, 1 not. */
    template <typename Run>
    int finishRun(Run &run, ompl_core::OutputFile &json, bool verbose)
    {
        if (json.isOpen())
        {
            ompl_core::writeRunJson(json.stream(), run.record());
            json.commit();
        }
        run.phases().checks = run.phases().lap();
        if (verbose)
            run.phases().print(std::cout);
        return run.solved() ? 0 : 1;
    }

    /** @throws ompl_core::InputError unless seed is in [1, 2^32 - 1] and a given time limit is positive. */
    inline void checkSeedAndTimeLimit(long long seed, bool timeLimitGiven, double timeLimit)
    {
        if (seed < 1 || seed > 4294967295LL)
            throw ompl_core::InputError("--seed must be in [1, 4294967295], got " + std::to_string(seed));
        if (timeLimitGiven && !(timeLimit > 0.0))
            throw ompl_core::InputError("--time-limit must be positive");
    }

    /** Parses the command line into options (the app's own options are in extra, which also
        receives the common ones for --help); usage is printed first by --help.
        @returns false when the program should exit with exitCode (help shown: 0, no scene: 2).
        @throws ompl_core::InputError for a bad seed or time limit; boost errors for malformed options. */
    inline bool parseCommandLine(int argc, char **argv, const std::string &usage,
                                 const std::string &plannerHelp,
                                 boost::program_options::options_description &extra, CommonOptions &options,
                                 int &exitCode)
    {
        namespace po = boost::program_options;
        po::options_description named("Options");
        named.add_options()("help,h", "print this help and exit")(
            "planner", po::value(&options.planner)->default_value(options.planner), plannerHelp.c_str())(
            "seed", po::value(&options.seed)->default_value(1), "random seed (positive)")(
            "param", po::value(&options.params)->composing(),
            "NAME=VALUE: set a declared parameter of the planner (repeatable; after the scene's)")(
            "time-limit", po::value(&options.timeLimit),
            "planning time limit in seconds (default: the scene's; inf or above 1e8: none; Ctrl-C ends a run "
            "early and still writes its results)")("json", po::value(&options.json),
                                                   "write the result as JSON to this file")(
            "svg", po::value(&options.svg), "write a top-down picture of the plan to this SVG file")(
            "html", po::value(&options.html),
            "write a 3-D view of the plan, animated, to this self-contained HTML file (needs three.js from "
            "Debian's libjs-three)")("verbose,v", po::bool_switch(&options.verbose),
                                     "print OMPL's informational messages")(
            "list-params", po::bool_switch(&options.listParams),
            "print the planner's parameters (values after the scene's and --param settings, ranges) and "
            "exit");
        named.add(extra);
        const po::variables_map vm = ompl_core::parseCommandLine(argc, argv, named, "scene", options.scene);
        if (vm.count("help") || options.scene.empty())
        {
            std::cout << usage << "Exit status: 0 solved, 1 not solved, 2 bad input.\n\n" << named;
            exitCode = vm.count("help") ? 0 : 2;
            return false;
        }
        checkSeedAndTimeLimit(options.seed, vm.count("time-limit") > 0, options.timeLimit);
        if (!options.html.empty())
            ompl_core::requireThreeJs();  // before planning, not after it
        return true;
    }

    /** Parses the command line with parse (false: exit with its code), sets OMPL's log level and
        runs; turns bad command lines and bad input into exit code 2, and an output file that could
        not be written into exit code 1, with a message. */
    template <typename Options>
    int runApp(const char *name, const std::function<bool(Options &, int &)> &parse,
               const std::function<int(const Options &)> &run)
    {
        return ompl_core::exitStatusOf<boost::program_options::error>(
            name,
            [&]
            {
                Options options;
                int exitCode = 0;
                if (!parse(options, exitCode))
                    return exitCode;
                ompl::msg::setLogLevel(options.common.verbose ? ompl::msg::LOG_INFO : ompl::msg::LOG_WARN);
                return run(options);
            });
    }
}  // namespace apps
