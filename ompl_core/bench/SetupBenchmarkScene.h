/* The part of a benchmark scene that every kind of OMPL setup shares: planners checked by making them,
   each run a single-run ompl::tools::Benchmark on a fresh setup, the run record as run properties. */
#pragma once

#include "ompl_core/bench/BenchmarkScene.h"
#include "ompl_core/bench/PlannerSettings.h"
#include "ompl_core/bench/RunProperties.h"
#include "ompl_core/run/GlobalSeed.h"

#include <memory>
#include <string>
#include <vector>

namespace ompl_core
{
    /** A BenchmarkScene whose runs plan on a Setup (a geometric or control SimpleSetup): each run
        makes a setup afresh (makeSetup()), seeds OMPL again just before solving (reseedOmpl()),
        runs it once through ompl::tools::Benchmark, and adds
        the seed and the run record (runDetails()) to the run's properties. */
    template <typename Setup>
    class SetupBenchmarkScene : public BenchmarkScene
    {
    public:
        /** Makes a setup for each planner (see BenchmarkScene::checkPlanners()). */
        void checkPlanners(const std::vector<BenchmarkPlanner> &planners,
                           const BenchmarkProblem &problem) override
        {
            std::vector<std::unique_ptr<Setup>> setups;
            std::vector<ompl::base::PlannerPtr> made;
            for (const BenchmarkPlanner &planner : planners)
            {
                setups.push_back(makeSetup(planner, problem, 1));
                made.push_back(setups.back()->getPlanner());
            }
            requireProblemParametersUsed(problem, made);
        }

        /** One single-run Benchmark on a fresh setup (see BenchmarkScene::run()). */
        SceneRun run(const BenchmarkPlanner &planner, const BenchmarkProblem &problem, std::uint32_t seed,
                     const ompl::tools::Benchmark::Request &request, bool wantPath) override
        {
            const std::unique_ptr<Setup> setup = makeSetup(planner, problem, seed);
            ompl::tools::Benchmark benchmark(*setup, problem.name);
            benchmark.addPlanner(setup->getPlanner());
            benchmark.setPreRunEvent([seed](const ompl::base::PlannerPtr &) { reseedOmpl(seed); });
            benchmark.setPostRunEvent(
                [&](const ompl::base::PlannerPtr &, ompl::tools::Benchmark::RunProperties &properties)
                {
                    properties["seed INTEGER"] = std::to_string(seed);
                    addRunProperties(runDetails(*setup, {problem.name, planner.type, seed, request.maxTime}),
                                     properties);
                });
            benchmark.benchmark(request);
            SceneRun run;
            run.experiment = benchmark.getRecordedExperimentData();
            describeSolution(*setup, wantPath, run);
            return run;
        }

    protected:
        /** A setup for planner, made after seeding OMPL with seed, with the planner and its
            parameters (benchmarkSettings()) in place and labelled.
            @throws InputError for an unknown planner or a bad parameter, at its cfg line. */
        virtual std::unique_ptr<Setup> makeSetup(const BenchmarkPlanner &planner,
                                                 const BenchmarkProblem &problem,
                                                 std::uint32_t seed) const = 0;

        /** The details of the run setup has just made (called after Benchmark's own properties). */
        virtual RunRecord runDetails(Setup &setup, const RunDescription &run) = 0;

        /** Sets run's solved, path length and, when wantPath, path text, after the run. */
        virtual void describeSolution(Setup &setup, bool wantPath, SceneRun &run) = 0;
    };
}  // namespace ompl_core
