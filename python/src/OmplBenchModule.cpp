// The C++ side of the Python module ompl_bench (python/ompl_bench/__init__.py adds to_database()):
// a benchmark config run as ompl_mm_benchmark runs it, without the GIL, stopped by Ctrl-C.
#include "ModuleSupport.h"
#include "ompl_bench/app/BenchmarkSceneLoading.h"
#include "ompl_core/bench/BenchmarkRunner.h"

#include <ompl/util/Console.h>

#include <algorithm>
#include <iostream>

namespace py = pybind11;

namespace
{
    /** OMPL's messages at most at warning level while it lives (a benchmark's runs would log a
        dozen lines each), the caller's level afterwards. */
    class QuietOmpl
    {
    public:
        QuietOmpl() : level_(ompl::msg::getLogLevel())
        {
            ompl::msg::setLogLevel(std::max(level_, ompl::msg::LOG_WARN));
        }
        ~QuietOmpl() { ompl::msg::setLogLevel(level_); }
        QuietOmpl(const QuietOmpl &) = delete;
        QuietOmpl &operator=(const QuietOmpl &) = delete;

    private:
        ompl::msg::LogLevel level_;
    };

    /** runBenchmark on the cfg at configFile, as ompl_mm_benchmark CONFIG --shard shard [--output
        output] makes it; progress lines on standard error when progress. */
    std::vector<std::string> runConfig(const std::string &configFile, const std::string &shardText,
                                       const std::string &output, bool progress)
    {
        const ompl_core::Shard shard = ompl_core::parseShard(shardText);
        ompl_core::BenchmarkConfig config = ompl_core::loadBenchmarkConfig(configFile);
        if (!output.empty())
            config.output = output;
        const QuietOmpl quiet;
        ompl_python::PythonSignalStop stop;
        std::vector<std::string> written;
        try
        {
            const py::gil_scoped_release release;
            written = ompl_core::runBenchmark(
                config, shard,
                [&](const ompl_core::BenchmarkProblem &problem)
                { return ompl_bench::loadBenchmarkScene(problem, config.planners, config.simulate); },
                progress ? &std::cerr : nullptr, [&] { return stop.requested(); });
        }
        catch (const ompl_core::BenchmarkInterrupted &)
        {
            stop.raiseIfInterrupted();
            throw;
        }
        return written;
    }
}  // namespace

PYBIND11_MODULE(_ompl_bench, m)
{
    m.doc() = "Benchmarks of ompl_mm and ompl_phys scenes: the C++ side of ompl_bench.run().";
    ompl_python::translateErrors();
    m.def("run_config", &runConfig, py::arg("config"), py::arg("shard"), py::arg("output"),
          py::arg("progress"),
          "Runs the benchmark cfg (shard 'K/N', output folder or '' for the cfg's) and returns every file "
          "written. Raises ompl_core.InputError for bad input, KeyboardInterrupt on Ctrl-C (after the "
          "run in progress).");
}
