// Tests for BenchmarkLog: addRuns merges single-run experiments into one (runs of a planner appended,
// new planners added at the end, host and setup from the first, durations summed), describe() sets the
// header, and the log written, on geometric and control setups, is OMPL's format with the OMPL version
// on its first line.
#include "ompl_core/bench/BenchmarkLog.h"

#include <ompl/base/PlannerStatus.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/control/SimpleSetup.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Time.h>

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <sstream>
#include <string>

using namespace ompl_core;
using Experiment = ompl::tools::Benchmark::CompleteExperiment;
using PlannerExperiment = ompl::tools::Benchmark::PlannerExperiment;

namespace
{
    /** A setup in the unit square, only to construct logs. */
    class LogTest : public ::testing::Test
    {
    protected:
        LogTest() : setup_(makeSpace()) {}

        static ompl::base::StateSpacePtr makeSpace()
        {
            auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
            space->setBounds(0.0, 1.0);
            return space;
        }

        ompl::geometric::SimpleSetup setup_;
    };

    /** The time point "seconds" after the epoch. */
    ompl::time::point timeAt(long seconds)
    {
        return ompl::time::point(std::chrono::seconds(seconds));
    }

    /** A single-run experiment as a one-run Benchmark would record it: planner's run with time
        and seed, a progress record of one time point, and the host's details. */
    Experiment singleRun(const std::string &planner, const std::string &time, const std::string &seed,
                         const std::string &host, double duration, long start)
    {
        Experiment experiment;
        experiment.name = "single run";
        experiment.maxTime = 99.0;
        experiment.maxMem = 99.0;
        experiment.runCount = 1;
        experiment.seed = 99;
        experiment.startTime = timeAt(start);
        experiment.totalDuration = duration;
        experiment.host = host;
        experiment.cpuInfo = "cpu of " + host;
        experiment.setupInfo = "setup of " + host + "\n";
        PlannerExperiment run;
        run.name = planner;
        run.runs.resize(1);
        run.runs[0].insert({{"time REAL", time}, {"seed INTEGER", seed}});
        run.progressPropertyNames = {"best cost REAL", "time REAL"};
        run.runsProgressData = {{{{"best cost REAL", "1." + seed}, {"time REAL", time}}}};
        run.common["range"] = "0.5";
        experiment.planners = {run};
        return experiment;
    }

    /** OMPL's line of planner status names. */
    std::string statusLine()
    {
        std::string line = "status";
        for (int i = 0; i < ompl::base::PlannerStatus::TYPE_COUNT; ++i)
            line +=
                "|" +
                ompl::base::PlannerStatus(static_cast<ompl::base::PlannerStatus::StatusType>(i)).asString();
        return line;
    }
}  // namespace

TEST(OmplVersion, IsTheVersionOfTheHeaders)
{
    // as CMake's package of OMPL says (Debian's OMPL 1.5.2 leaves the header's OMPL_VERSION empty)
    EXPECT_EQ(omplVersion(), OMPL_MM_TEST_OMPL_VERSION);
}

TEST_F(LogTest, AddRunsAppendsRunsOfAKnownPlannerAndAddsNewPlannersAtTheEnd)
{
    BenchmarkLog log(setup_, "corridor");
    log.addRuns(singleRun("geometric_RRT", "0.5", "11", "host-a", 0.25, 1000));
    log.addRuns(singleRun("geometric_PRM", "0.125", "21", "host-b", 0.5, 2000));
    log.addRuns(singleRun("geometric_RRT", "0.75", "12", "host-c", 1.0, 3000));

    const Experiment &merged = log.getRecordedExperimentData();
    EXPECT_EQ(merged.name, "corridor");
    // the first run gives the host and setup; every run adds its duration
    EXPECT_EQ(merged.host, "host-a");
    EXPECT_EQ(merged.cpuInfo, "cpu of host-a");
    EXPECT_EQ(merged.setupInfo, "setup of host-a\n");
    EXPECT_EQ(merged.startTime, timeAt(1000));
    EXPECT_EQ(merged.totalDuration, 1.75);
    ASSERT_EQ(merged.planners.size(), 2u);

    const PlannerExperiment &rrt = merged.planners[0];
    EXPECT_EQ(rrt.name, "geometric_RRT");
    ASSERT_EQ(rrt.runs.size(), 2u);
    EXPECT_EQ(rrt.runs[0].at("seed INTEGER"), "11");
    EXPECT_EQ(rrt.runs[1].at("seed INTEGER"), "12");
    EXPECT_EQ(rrt.runs[1].at("time REAL"), "0.75");
    ASSERT_EQ(rrt.runsProgressData.size(), 2u);
    EXPECT_EQ(rrt.runsProgressData[0].at(0).at("best cost REAL"), "1.11");
    EXPECT_EQ(rrt.runsProgressData[1].at(0).at("best cost REAL"), "1.12");
    EXPECT_EQ(rrt.common.size(), 1u);
    EXPECT_EQ(rrt.common.at("range"), "0.5");

    const PlannerExperiment &prm = merged.planners[1];
    EXPECT_EQ(prm.name, "geometric_PRM");
    ASSERT_EQ(prm.runs.size(), 1u);
    EXPECT_EQ(prm.runs[0].at("seed INTEGER"), "21");
    EXPECT_EQ(prm.runsProgressData.size(), 1u);
}

TEST_F(LogTest, DescribeSetsTheHeaderWhateverTheRunsSay)
{
    BenchmarkLog log(setup_, "corridor");
    log.describe(10.0, 2048.0, 2, 42);
    log.addRuns(singleRun("geometric_RRT", "0.5", "11", "host-a", 0.25, 1000));
    const Experiment &merged = log.getRecordedExperimentData();
    EXPECT_EQ(merged.maxTime, 10.0);
    EXPECT_EQ(merged.maxMem, 2048.0);
    EXPECT_EQ(merged.runCount, 2u);
    EXPECT_EQ(merged.seed, 42u);
    // and after runs were added
    log.describe(2.5, 512.0, 7, 4294967295u);
    EXPECT_EQ(merged.maxTime, 2.5);
    EXPECT_EQ(merged.maxMem, 512.0);
    EXPECT_EQ(merged.runCount, 7u);
    EXPECT_EQ(merged.seed, 4294967295u);
}

TEST_F(LogTest, WritesOmplsLogFormatWithTheVersion)
{
    BenchmarkLog log(setup_, "corridor");
    log.describe(10.0, 2048.0, 2, 42);
    log.addRuns(singleRun("geometric_RRT", "0.5", "11", "host-a", 0.25, 1000));
    log.addRuns(singleRun("geometric_PRM", "0.125", "21", "host-b", 0.5, 2000));
    log.addRuns(singleRun("geometric_RRT", "0.75", "12", "host-c", 1.0, 3000));
    std::ostringstream out;
    ASSERT_TRUE(log.saveResultsToStream(out));
    const std::string expected = "OMPL version " OMPL_MM_TEST_OMPL_VERSION
                                 "\n"
                                 "Experiment corridor\n"
                                 "0 experiment properties\n"
                                 "Running on host-a\n"
                                 "Starting at " +
                                 ompl::time::as_string(timeAt(1000)) +
                                 "\n"
                                 "<<<|\n"
                                 "setup of host-a\n"
                                 "|>>>\n"
                                 "<<<|\n"
                                 "cpu of host-a|>>>\n"
                                 "42 is the random seed\n"
                                 "10 seconds per run\n"
                                 "2048 MB per run\n"
                                 "2 runs per planner\n"
                                 "1.75 seconds spent to collect the data\n"
                                 "1 enum type\n" +
                                 statusLine() +
                                 "\n"
                                 "2 planners\n"
                                 "geometric_RRT\n"
                                 "1 common properties\n"
                                 "range = 0.5\n"
                                 "2 properties for each run\n"
                                 "seed INTEGER\n"
                                 "time REAL\n"
                                 "2 runs\n"
                                 "11; 0.5; \n"
                                 "12; 0.75; \n"
                                 "2 progress properties for each run\n"
                                 "best cost REAL\n"
                                 "time REAL\n"
                                 "2 runs\n"
                                 "1.11,0.5,;\n"
                                 "1.12,0.75,;\n"
                                 ".\n"
                                 "geometric_PRM\n"
                                 "1 common properties\n"
                                 "range = 0.5\n"
                                 "2 properties for each run\n"
                                 "seed INTEGER\n"
                                 "time REAL\n"
                                 "1 runs\n"
                                 "21; 0.125; \n"
                                 "2 progress properties for each run\n"
                                 "best cost REAL\n"
                                 "time REAL\n"
                                 "1 runs\n"
                                 "1.21,0.125,;\n"
                                 ".\n";
    EXPECT_EQ(out.str(), expected);
}

TEST_F(LogTest, LogOfControlSetups)
{
    auto controls = std::make_shared<ompl::control::RealVectorControlSpace>(makeSpace(), 1);
    ompl::control::SimpleSetup controlSetup(controls);
    BenchmarkLog log(controlSetup, "pushing");
    log.describe(1.0, 64.0, 1, 5);
    log.addRuns(singleRun("control_KPIECE1", "0.5", "11", "host-a", 0.25, 1000));
    EXPECT_EQ(log.getExperimentName(), "pushing");
    std::ostringstream out;
    ASSERT_TRUE(log.saveResultsToStream(out));
    EXPECT_EQ(out.str().substr(0, out.str().find("Running on")),
              "OMPL version " OMPL_MM_TEST_OMPL_VERSION "\nExperiment pushing\n0 experiment properties\n");
}

TEST_F(LogTest, EmptyLogIsNotWritten)
{
    BenchmarkLog log(setup_, "corridor");
    log.describe(10.0, 2048.0, 2, 42);
    std::ostringstream out;
    EXPECT_FALSE(log.saveResultsToStream(out));
    EXPECT_EQ(out.str(), "");
}

TEST_F(LogTest, FailedStreamIsReported)
{
    BenchmarkLog log(setup_, "corridor");
    log.describe(10.0, 2048.0, 1, 1);
    log.addRuns(singleRun("geometric_RRT", "0.5", "11", "host-a", 0.25, 1000));
    std::ostringstream out;
    out.setstate(std::ios::badbit);
    EXPECT_FALSE(log.saveResultsToStream(out));
}
