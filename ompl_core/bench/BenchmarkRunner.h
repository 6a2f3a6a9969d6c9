/* Running a benchmark config: every scheduled run, progress on the terminal, one log per problem. */
#pragma once

#include "ompl_core/bench/BenchmarkScene.h"
#include "ompl_core/bench/RunSchedule.h"

#include <functional>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ompl_core
{
    /** Loads a problem's scene. @throws InputError for a bad scene file or a scene of no known kind. */
    using BenchmarkSceneLoader = std::function<std::unique_ptr<BenchmarkScene>(const BenchmarkProblem &)>;

    /** Asked before each run of a benchmark; true stops the benchmark there (a run in progress
        ends at its time limit first: OMPL's Benchmark takes no other stop). */
    using BenchmarkStop = std::function<bool()>;

    /** Thrown by runBenchmark() when its BenchmarkStop asked it to stop. */
    class BenchmarkInterrupted : public std::runtime_error
    {
    public:
        using std::runtime_error::runtime_error;
    };

    /** The log of problem: "<output>/<cfg name>.log" for a config of one problem,
        "<output>/<cfg name>.<problem>.log" for several; a shard other than 1/1 adds
        ".shard-K-of-N" before ".log". */
    std::string benchmarkLogPath(const BenchmarkConfig &config, const BenchmarkProblem &problem,
                                 const Shard &shard);

    /** Loads every problem's scene and checks its planners (before any run), then makes the runs
        of shard, each in a fresh setup, and writes one log per problem (benchmarkLogPath()) and
        the solution paths the config asks for. Reports each run to progress (planner, run k of n,
        elapsed time, successes, estimated time left) unless it is null. Asks stop, when given,
        before each run.
        @returns the files written.
        @throws InputError for bad input, OutputError when a file cannot be written,
        BenchmarkInterrupted when stop said so (the logs of problems finished before are written,
        the one in progress is not). */
    std::vector<std::string> runBenchmark(const BenchmarkConfig &config, const Shard &shard,
                                          const BenchmarkSceneLoader &load, std::ostream *progress,
                                          const BenchmarkStop &stop = nullptr);
}  // namespace ompl_core
