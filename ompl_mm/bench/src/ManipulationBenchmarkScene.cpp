#include "ompl_mm/bench/ManipulationBenchmarkScene.h"

#include "ompl_core/run/GlobalSeed.h"
#include "ompl_mm/io/ManipulationRunResult.h"
#include "ompl_mm/io/PathFile.h"

#include <sstream>

namespace ompl_mm
{
    ManipulationBenchmarkScene::ManipulationBenchmarkScene(Scene scene, PrimitiveFactory factory)
        : scene_(std::move(scene)), factory_(std::move(factory)), logSetup_(scene_, factory_)
    {
    }

    std::unique_ptr<ompl_core::BenchmarkLog> ManipulationBenchmarkScene::makeLog(
        const std::string &experimentName)
    {
        return std::make_unique<ompl_core::BenchmarkLog>(logSetup_, experimentName);
    }

    std::unique_ptr<ManipulationSetup> ManipulationBenchmarkScene::makeSetup(
        const ompl_core::BenchmarkPlanner &planner, const ompl_core::BenchmarkProblem &problem,
        std::uint32_t seed) const
    {
        ompl_core::reseedOmpl(seed);
        auto setup = std::make_unique<ManipulationSetup>(scene_, factory_);
        if (setup->goalFault())  // the scene is the benchmark's input
            throw *setup->goalFault();
        if (planner.type != scene_.planner)
        {
            ManipulationSetup::plannerRegistry().require(planner.type, planner.where);
            setup->selectPlanner(planner.type);
        }
        setup->applyParameters(ompl_core::benchmarkSettings(*setup->getPlanner(), problem, planner));
        setup->getPlanner()->setName(planner.label);
        if (const std::shared_ptr<MOPL> mopl = setup->mopl())
            mopl->setSeed(seed);
        return setup;
    }

    ompl_core::RunRecord ManipulationBenchmarkScene::runDetails(ManipulationSetup &setup,
                                                                const ompl_core::RunDescription &run)
    {
        return manipulationRunResult(run, setup).details;
    }

    void ManipulationBenchmarkScene::describeSolution(ManipulationSetup &setup, bool wantPath,
                                                      ompl_core::SceneRun &run)
    {
        run.solved = setup.getProblemDefinition()->hasExactSolution();
        if (!run.solved)
            return;
        run.pathLength = setup.manipulationPath().toolPathLength();
        if (wantPath)
        {
            std::ostringstream text;
            writePathFile(text, setup.manipulationPath());
            run.pathText = text.str();
        }
    }
}  // namespace ompl_mm
