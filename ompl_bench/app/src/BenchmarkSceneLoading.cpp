#include "ompl_bench/app/BenchmarkSceneLoading.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_mm/bench/ManipulationBenchmarkScene.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mmphys/bench/SimulatedBenchmarkScene.h"
#include "ompl_mmphys/primitives/PhysicsPrimitives.h"
#include "ompl_phys/bench/PhysicsBenchmarkScene.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <tinyxml2.h>

#include <filesystem>

namespace ompl_bench
{
    namespace
    {
        enum class SceneKind
        {
            Manipulation,
            Physics,
        };

        const char *kindName(SceneKind kind)
        {
            return kind == SceneKind::Manipulation ? "an ompl_mm scene" : "a physics scene";
        }

        SceneKind sceneKind(const ompl_core::BenchmarkProblem &problem)
        {
            std::error_code error;
            if (!std::filesystem::is_regular_file(problem.scene, error))
                throw ompl_core::InputError(problem.sceneWhere,
                                            "scene file '" + problem.scene + "' not found");
            tinyxml2::XMLDocument document;
            const std::string text = ompl_core::readInputFile(problem.scene, "scene file");
            document.Parse(text.c_str(), text.size());
            const tinyxml2::XMLElement *root = document.RootElement();
            const std::string name = root ? root->Name() : "";
            if (name == "scene")
                return SceneKind::Manipulation;
            if (name == "physics_scene")
                return SceneKind::Physics;
            throw ompl_core::InputError(problem.sceneWhere,
                                        "scene file '" + problem.scene +
                                            "' is neither an ompl_mm scene (<scene>) nor a physics scene "
                                            "(<physics_scene>)");
        }

        bool registered(SceneKind kind, const std::string &planner)
        {
            return kind == SceneKind::Manipulation
                       ? ompl_mm::ManipulationSetup::plannerRegistry().has(planner)
                       : ompl_phys::PhysicsSetup::plannerRegistry().has(planner);
        }

        std::string known(SceneKind kind)
        {
            return kind == SceneKind::Manipulation ? ompl_mm::ManipulationSetup::plannerRegistry().nameList()
                                                   : ompl_phys::PhysicsSetup::plannerRegistry().nameList();
        }
    }  // namespace

    std::unique_ptr<ompl_core::BenchmarkScene> loadBenchmarkScene(
        const ompl_core::BenchmarkProblem &problem, const std::vector<ompl_core::BenchmarkPlanner> &planners,
        bool simulate)
    {
        const SceneKind kind = sceneKind(problem);
        const SceneKind other =
            kind == SceneKind::Manipulation ? SceneKind::Physics : SceneKind::Manipulation;
        for (const ompl_core::BenchmarkPlanner &planner : planners)
        {
            if (registered(kind, planner.type))
                continue;
            const std::string scene = "problem '" + problem.name + "' is " + kindName(kind);
            if (registered(other, planner.type))
                throw ompl_core::InputError(planner.where, "planner '" + planner.type + "' plans " +
                                                               kindName(other) + "; " + scene +
                                                               " (its planners: " + known(kind) + ")");
            throw ompl_core::InputError(planner.where, "unknown planner '" + planner.type + "' (" + scene +
                                                           "; its planners: " + known(kind) + ")");
        }
        if (kind == SceneKind::Manipulation && simulate)
            return std::make_unique<ompl_mmphys::SimulatedBenchmarkScene>(ompl_mm::loadScene(problem.scene));
        if (kind == SceneKind::Manipulation)
            return std::make_unique<ompl_mm::ManipulationBenchmarkScene>(
                ompl_mm::loadScene(problem.scene), ompl_mmphys::physicsPrimitiveFactory());
        return std::make_unique<ompl_phys::PhysicsBenchmarkScene>(
            std::make_shared<const ompl_phys::PhysicsScene>(ompl_phys::loadPhysicsScene(problem.scene)));
    }
}  // namespace ompl_bench
