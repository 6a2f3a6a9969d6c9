#include "ompl_phys/bench/PhysicsBenchmarkScene.h"

#include "ompl_core/run/GlobalSeed.h"
#include "ompl_phys/io/PhysicsPathFile.h"
#include "ompl_phys/io/PhysicsRunResult.h"

#include <sstream>

namespace ompl_phys
{
    PhysicsBenchmarkScene::PhysicsBenchmarkScene(PhysicsScenePtr scene)
        : scene_(std::move(scene)), logSetup_(scene_)
    {
    }

    std::unique_ptr<ompl_core::BenchmarkLog> PhysicsBenchmarkScene::makeLog(const std::string &experimentName)
    {
        return std::make_unique<ompl_core::BenchmarkLog>(logSetup_, experimentName);
    }

    std::unique_ptr<PhysicsSetup> PhysicsBenchmarkScene::makeSetup(const ompl_core::BenchmarkPlanner &planner,
                                                                   const ompl_core::BenchmarkProblem &problem,
                                                                   std::uint32_t seed) const
    {
        ompl_core::reseedOmpl(seed);
        auto setup = std::make_unique<PhysicsSetup>(scene_);
        if (setup->goalFault())  // the scene is the benchmark's input
            throw *setup->goalFault();
        PhysicsSetup::plannerRegistry().require(planner.type, planner.where);
        setup->setPlannerByName(planner.type);
        ompl_core::applyParameters(*setup->getPlanner(),
                                   ompl_core::benchmarkSettings(*setup->getPlanner(), problem, planner));
        setup->getPlanner()->setName(planner.label);
        return setup;
    }

    ompl_core::RunRecord PhysicsBenchmarkScene::runDetails(PhysicsSetup &setup,
                                                           const ompl_core::RunDescription &run)
    {
        simulated_.reset();
        if (setup.haveExactSolutionPath())
            simulated_ = simulatePath(setup, setup.getSolutionPath());
        return physicsRunResult(run, setup, simulated_ ? &*simulated_ : nullptr).details;
    }

    void PhysicsBenchmarkScene::describeSolution(PhysicsSetup &setup, bool wantPath, ompl_core::SceneRun &run)
    {
        run.solved = simulated_.has_value();
        if (!run.solved)
            return;
        run.pathLength = setup.getSolutionPath().length();
        if (wantPath)
        {
            std::ostringstream text;
            writeSimulatedPathFile(text, setup, *simulated_);
            run.pathText = text.str();
        }
    }
}  // namespace ompl_phys
