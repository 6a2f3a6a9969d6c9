#include "ompl_mmphys/bench/SimulatedBenchmarkScene.h"

#include "ompl_mmphys/io/PhysicsCheckRecord.h"
#include "ompl_mmphys/primitives/PhysicsPrimitives.h"

namespace ompl_mmphys
{
    SimulatedBenchmarkScene::SimulatedBenchmarkScene(ompl_mm::Scene scene)
        : ompl_mm::ManipulationBenchmarkScene(std::move(scene), physicsPrimitiveFactory())
    {
    }

    ompl_core::RunRecord SimulatedBenchmarkScene::runDetails(ompl_mm::ManipulationSetup &setup,
                                                             const ompl_core::RunDescription &run)
    {
        ompl_core::RunRecord details = ManipulationBenchmarkScene::runDetails(setup, run);
        if (setup.getProblemDefinition()->hasExactSolution())
            details.addRecord("physics_check",
                              physicsCheckRecord(checkPlan(setup, setup.manipulationPath())));
        return details;
    }
}  // namespace ompl_mmphys
