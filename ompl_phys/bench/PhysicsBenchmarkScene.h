#pragma once

#include "ompl_core/bench/SetupBenchmarkScene.h"
#include "ompl_phys/control/PathSimulation.h"
#include "ompl_phys/control/PhysicsSetup.h"

#include <optional>

namespace ompl_phys
{
    /** A physics scene in a benchmark: each run builds a PhysicsSetup afresh as ompl_phys_plan does
        (OMPL seeded, the setup, the planner and its parameters), so `ompl_phys_plan SCENE --planner
        TYPE --seed S` with the run's parameters plans that run again. A solved run's controls are
        re-simulated after the run, and the run logs action, power, smoothness, whether the
        re-simulation reached the goal, the propagator's counters and the seed
        (physicsRunResult()). */
    class PhysicsBenchmarkScene : public ompl_core::SetupBenchmarkScene<PhysicsSetup>
    {
    public:
        /** @throws ompl_core::InputError when the scene's problem cannot be planned. */
        explicit PhysicsBenchmarkScene(PhysicsScenePtr scene);

        double timeLimit() const override { return scene_->timeLimit; }

        std::unique_ptr<ompl_core::BenchmarkLog> makeLog(const std::string &experimentName) override;

    protected:
        /** A setup made as the plan app makes one. */
        std::unique_ptr<PhysicsSetup> makeSetup(const ompl_core::BenchmarkPlanner &planner,
                                                const ompl_core::BenchmarkProblem &problem,
                                                std::uint32_t seed) const override;
        /** The run record\'s details: the re-simulation of a solution and physicsRunResult(). */
        ompl_core::RunRecord runDetails(PhysicsSetup &setup, const ompl_core::RunDescription &run) override;
        /** Whether the run solved, its path length and path file. */
        void describeSolution(PhysicsSetup &setup, bool wantPath, ompl_core::SceneRun &run) override;

    private:
        PhysicsScenePtr scene_;
        PhysicsSetup logSetup_;                   ///< what the logs' Benchmark base is built on
        std::optional<SimulatedPath> simulated_;  ///< the last run's re-simulated solution
    };
}  // namespace ompl_phys
