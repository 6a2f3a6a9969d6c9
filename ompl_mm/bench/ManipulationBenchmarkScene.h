#pragma once

#include "ompl_core/bench/SetupBenchmarkScene.h"
#include "ompl_mm/scene/Scene.h"
#include "ompl_mm/setup/ManipulationSetup.h"

namespace ompl_mm
{
    /** An ompl_mm scene in a benchmark: each run builds a ManipulationSetup afresh as ompl_mm_plan
        does (OMPL seeded, the setup, the planner and its parameters, MOPL's own seed), so
        `ompl_mm_plan SCENE --planner TYPE --seed S` with the run's parameters plans that run again.
        Runs log MOPL's statistics, the path's length, vertices and primitives as run properties
        (manipulationRunResult()), and the seed. */
    class ManipulationBenchmarkScene : public ompl_core::SetupBenchmarkScene<ManipulationSetup>
    {
    public:
        /** Runs on scene, its primitives built by factory.
            @throws ompl_core::InputError when the scene's problem cannot be planned. */
        explicit ManipulationBenchmarkScene(Scene scene, PrimitiveFactory factory = PrimitiveFactory());

        double timeLimit() const override { return scene_.timeLimit; }

        std::unique_ptr<ompl_core::BenchmarkLog> makeLog(const std::string &experimentName) override;

    protected:
        /** A setup made as the plan app makes one. */
        std::unique_ptr<ManipulationSetup> makeSetup(const ompl_core::BenchmarkPlanner &planner,
                                                     const ompl_core::BenchmarkProblem &problem,
                                                     std::uint32_t seed) const override;
        /** The run record\'s details: manipulationRunResult(). */
        ompl_core::RunRecord runDetails(ManipulationSetup &setup,
                                        const ompl_core::RunDescription &run) override;
        /** Whether the run solved, its path length and path file. */
        void describeSolution(ManipulationSetup &setup, bool wantPath, ompl_core::SceneRun &run) override;

    private:
        Scene scene_;
        PrimitiveFactory factory_;
        ManipulationSetup logSetup_;  ///< what the logs' Benchmark base is built on
    };
}  // namespace ompl_mm
