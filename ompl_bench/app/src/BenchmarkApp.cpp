#include "ompl_bench/app/BenchmarkApp.h"

#include "ompl_bench/app/BenchmarkSceneLoading.h"
#include "ompl_core/bench/BenchmarkRunner.h"
#include "ompl_core/run/CommandLine.h"
#include "ompl_core/run/ExitStatus.h"

#include <ompl/util/Console.h>

#include <boost/program_options.hpp>

#include <filesystem>
#include <iostream>

namespace ompl_bench
{
    namespace po = boost::program_options;

    namespace
    {
        struct Options
        {
            std::string config;
            std::string shard{"1/1"};
            std::string output;  ///< overrides the cfg's output folder when set
            bool quiet{false};
        };

        /** Reads the command line into options; false when the program should exit with exitCode
            instead (after --help, or without a config). */
        bool parseOptions(int argc, const char *const *argv, const std::string &program, Options &options,
                          int &exitCode)
        {
            po::options_description named("Options");
            named.add_options()("help,h", "print this help")(
                "shard", po::value(&options.shard)->value_name("K/N"),
                "make only shard K of N: every N-th run from run K, logged to CONFIG.shard-K-of-N.log; the "
                "logs "
                "of all N shards merge with ompl_benchmark_statistics -a")(
                "output", po::value(&options.output)->value_name("DIR"),
                "write logs and paths into DIR instead of the cfg's output folder")(
                "quiet,q", po::bool_switch(&options.quiet), "print no progress");
            const po::variables_map vm =
                ompl_core::parseCommandLine(argc, argv, named, "config", options.config);
            if (vm.count("help") || options.config.empty())
            {
                std::cout
                    << "Usage: " << program
                    << " CONFIG.cfg [--shard K/N] [--output DIR] [--quiet]\n"
                       "Runs the benchmark that CONFIG.cfg describes (OMPL.app's ompl_benchmark format: "
                       "[problem], [benchmark],\n[planner]; see docs/benchmarks.md) and writes OMPL "
                       "benchmark logs for ompl_benchmark_statistics.\nExit status: 0 done, 1 an output "
                       "could not be written, 2 bad input.\n\n"
                    << named;
                exitCode = vm.count("help") ? 0 : 2;
                return false;
            }
            return true;
        }

        int run(const Options &options)
        {
            const ompl_core::Shard shard = ompl_core::parseShard(options.shard);
            ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
            ompl_core::BenchmarkConfig config = ompl_core::loadBenchmarkConfig(options.config);
            if (!options.output.empty())
                config.output = options.output;
            const std::vector<std::string> written = ompl_core::runBenchmark(
                config, shard,
                [&](const ompl_core::BenchmarkProblem &problem)
                { return loadBenchmarkScene(problem, config.planners, config.simulate); },
                options.quiet ? nullptr : &std::cerr);
            for (const std::string &file : written)
                std::cout << file << '\n';
            return 0;
        }
    }  // namespace

    int benchmarkMain(int argc, const char *const *argv)
    {
        const std::string program =
            argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "benchmark";
        return ompl_core::exitStatusOf<po::error>(
            program,
            [&]
            {
                Options options;
                int exitCode = 0;
                if (!parseOptions(argc, argv, program, options, exitCode))
                    return exitCode;
                return run(options);
            });
    }
}  // namespace ompl_bench
