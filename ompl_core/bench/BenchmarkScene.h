/* What the benchmark runner needs of a kind of scene (ompl_mm's, ompl_phys's): planners checked up front,
   single runs in fresh setups, and a log. */
#pragma once

#include "ompl_core/bench/BenchmarkConfig.h"
#include "ompl_core/bench/BenchmarkLog.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ompl_core
{
    /** What one run gave. */
    struct SceneRun
    {
        ompl::tools::Benchmark::CompleteExperiment experiment;  ///< the single run, as Benchmark logged it
        bool solved{false};                                     ///< an exact solution was found
        double pathLength{0.0};                                 ///< the solution's length, when solved
        std::string pathText;  ///< the solution as a path file, when solved and asked for
    };

    /** One problem's scene, loaded, as the benchmark runner drives it. Implementations build a fresh
        setup for every run, so a run's result depends on its seed alone. */
    class BenchmarkScene
    {
    public:
        virtual ~BenchmarkScene() = default;

        /** The time limit the scene file gives, seconds. */
        virtual double timeLimit() const = 0;

        /** Makes every planner once with its parameters (the scene's, then the problem's that it
            declares, then its own), so that errors show before any run.
            @throws InputError naming the cfg line of an unknown planner (or one of another kind of
            scene), of a parameter no planner declares, or of a bad value. */
        virtual void checkPlanners(const std::vector<BenchmarkPlanner> &planners,
                                   const BenchmarkProblem &problem) = 0;

        /** One run of planner on a fresh setup, everything seeded with seed; the path file when
            wantPath and solved. */
        virtual SceneRun run(const BenchmarkPlanner &planner, const BenchmarkProblem &problem,
                             std::uint32_t seed, const ompl::tools::Benchmark::Request &request,
                             bool wantPath) = 0;

        /** An empty log for this scene's runs, named experimentName; valid while the scene is. */
        virtual std::unique_ptr<BenchmarkLog> makeLog(const std::string &experimentName) = 0;
    };
}  // namespace ompl_core
