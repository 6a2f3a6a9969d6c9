#include "ompl_core/bench/BenchmarkLog.h"

#include <ompl/config.h>

#include <algorithm>
#include <sstream>

namespace ompl_core
{
    BenchmarkLog::BenchmarkLog(ompl::geometric::SimpleSetup &setup, const std::string &experimentName)
        : Benchmark(setup, experimentName)
    {
    }

    BenchmarkLog::BenchmarkLog(ompl::control::SimpleSetup &setup, const std::string &experimentName)
        : Benchmark(setup, experimentName)
    {
    }

    void BenchmarkLog::describe(double timeLimit, double memoryLimit, unsigned int runCount,
                                std::uint32_t seed)
    {
        exp_.maxTime = timeLimit;
        exp_.maxMem = memoryLimit;
        exp_.runCount = runCount;
        exp_.seed = seed;
    }

    void BenchmarkLog::addRuns(const CompleteExperiment &finished)
    {
        if (finished.planners.empty())
            return;
        if (exp_.planners.empty())
        {
            exp_.host = finished.host;
            exp_.cpuInfo = finished.cpuInfo;
            exp_.setupInfo = finished.setupInfo;
            exp_.startTime = finished.startTime;
            exp_.totalDuration = 0.0;
        }
        exp_.totalDuration += finished.totalDuration;
        for (const PlannerExperiment &planner : finished.planners)
        {
            auto known = std::find_if(exp_.planners.begin(), exp_.planners.end(),
                                      [&](const PlannerExperiment &p) { return p.name == planner.name; });
            if (known == exp_.planners.end())
            {
                exp_.planners.push_back(planner);
                continue;
            }
            known->runs.insert(known->runs.end(), planner.runs.begin(), planner.runs.end());
            known->runsProgressData.insert(known->runsProgressData.end(), planner.runsProgressData.begin(),
                                           planner.runsProgressData.end());
        }
    }

    bool BenchmarkLog::saveResultsToStream(std::ostream &out) const
    {
        std::ostringstream log;
        if (!Benchmark::saveResultsToStream(log))
            return false;
        std::string text = log.str();
        // OMPL 1.5.2 as Debian builds it writes an empty version
        const std::string firstLine = "OMPL version " + std::string(OMPL_VERSION) + "\n";
        if (text.compare(0, firstLine.size(), firstLine) == 0)
            text.replace(0, firstLine.size(), "OMPL version " + omplVersion() + "\n");
        out << text;
        return out.good();
    }

    std::string omplVersion()
    {
        return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
               std::to_string(OMPL_PATCH_VERSION);
    }
}  // namespace ompl_core
