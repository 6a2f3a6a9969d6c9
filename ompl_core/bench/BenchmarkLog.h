/* One experiment's OMPL benchmark log, gathered from runs made one at a time. */
#pragma once

#include <ompl/tools/benchmark/Benchmark.h>

#include <ostream>
#include <string>

namespace ompl_core
{
    /** An ompl::tools::Benchmark that makes no runs of its own: it gathers the runs of single-run
        Benchmarks (each in a setup of its own, so a run depends on its seed alone) into one
        experiment, and writes them in OMPL's log format, which ompl_benchmark_statistics reads.
        Unlike OMPL 1.5.2's, the log names the OMPL version. */
    class BenchmarkLog : public ompl::tools::Benchmark
    {
    public:
        /** A log for runs on geometric setups; setup only satisfies Benchmark's constructor. */
        BenchmarkLog(ompl::geometric::SimpleSetup &setup, const std::string &experimentName);
        /** A log for runs on control setups; setup only satisfies Benchmark's constructor. */
        BenchmarkLog(ompl::control::SimpleSetup &setup, const std::string &experimentName);

        /** Sets the header's time limit (seconds), memory limit (MB), runs per planner and seed. */
        void describe(double timeLimit, double memoryLimit, unsigned int runCount, std::uint32_t seed);

        /** Appends the runs of a finished Benchmark to its planner's (matched by the log's planner
            name, added at the end when new); the first run also gives the host, CPU and setup
            information, and every run adds its duration to the total. */
        void addRuns(const CompleteExperiment &finished);

        /** The log; false (with OMPL's warning) when it holds no runs. */
        bool saveResultsToStream(std::ostream &out) const override;
    };

    /** "MAJOR.MINOR.PATCH" of the OMPL headers compiled against. */
    std::string omplVersion();
}  // namespace ompl_core
