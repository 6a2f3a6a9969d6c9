/* An ompl_mm scene in a benchmark whose solutions are also executed in physics. */
#pragma once

#include "ompl_mm/bench/ManipulationBenchmarkScene.h"
#include "ompl_mmphys/simulation/PhysicsCheck.h"

namespace ompl_mmphys
{
    /** An ompl_mm scene in a benchmark (the cfg's `simulate = 1`): runs as
        ompl_mm::ManipulationBenchmarkScene's (with physicsPrimitiveFactory(), so pushes may be
        physics-aware), and each solved run's path checked in physics
        (checkPlan with default settings), its physics_check record (physicsCheckRecord) among the
        run's properties: physics_check_confirmed, physics_check_max_position_error_m, the metrics
        and the per-object errors. The check's time is no planning time. */
    class SimulatedBenchmarkScene : public ompl_mm::ManipulationBenchmarkScene
    {
    public:
        /** @throws ompl_core::InputError when the scene's problem cannot be planned. */
        explicit SimulatedBenchmarkScene(ompl_mm::Scene scene);

    protected:
        /** The base's details, then the physics check of a solved run's path. */
        ompl_core::RunRecord runDetails(ompl_mm::ManipulationSetup &setup,
                                        const ompl_core::RunDescription &run) override;
    };
}  // namespace ompl_mmphys
