#include "ompl_mm/geometric/ManipulationSetup.h"

#include "ompl_mm/scene/InputError.h"

namespace ompl_mm
{
    namespace
    {
        RobotModel loadRobot(const Scene &scene)
        {
            try
            {
                return RobotModel::fromUrdfFile(scene.robot.urdfFile);
            }
            catch (const ompl::Exception &e)
            {
                throw InputError(scene.robot.where, e.what());
            }
        }

        ManipulationModelPtr makeModel(const Scene &scene)
        {
            if (scene.planner != "mopl")
                throw InputError(SourceLocation{scene.file, 0},
                                 "unknown planner '" + scene.planner + "' (known: mopl)");
            return std::make_shared<ManipulationModel>(scene, loadRobot(scene));
        }
    }  // namespace

    ManipulationSetup::ManipulationSetup(const Scene &scene, const PrimitiveFactory &factory)
        : ompl::geometric::SimpleSetup(std::make_shared<ManipulationStateSpace>(makeModel(scene)))
    {
        space_ = std::static_pointer_cast<ManipulationStateSpace>(getStateSpace());
        model_ = space_->model();
        checker_ = std::make_shared<ManipulationValidityChecker>(si_);
        setStateValidityChecker(checker_);
        setStartFromScene(scene);
        goal_ = std::make_shared<ManipulationGoal>(si_);
        setGoal(goal_);
        mopl_ = std::make_shared<MOPL>(si_, factory.build(scene.primitives, space_.get()));
        applyPlannerParameters(scene);
        space_->setCollisionResolution(mopl_->getConnectStep());
        setPlanner(mopl_);
    }

    void ManipulationSetup::setStartFromScene(const Scene &scene)
    {
        const RobotModel &robot = model_->robot();
        if (scene.robotStart.size() != robot.dof())
            throw InputError(scene.robotStartWhere, "start has " + std::to_string(scene.robotStart.size()) +
                                                        " joint values but robot '" + robot.name() +
                                                        "' has " + std::to_string(robot.dof()) +
                                                        " moving joints");
        ompl::base::ScopedState<> start(space_);
        std::copy(scene.robotStart.begin(), scene.robotStart.end(), space_->robotValues(start.get()));
        for (unsigned int i = 0; i < model_->objectCount(); ++i)
        {
            const MovableObject &object = scene.objects[i];
            if (model_->restingSurface(object.start.position) < 0)
                throw InputError(object.where, "object '" + object.name + "' starts on no support surface");
            space_->setObjectPose(start.get(), i, object.start);
        }
        const std::string reason = checker_->explain(start.get());
        if (!reason.empty())
            throw InputError(scene.robotStartWhere, "the start state is invalid: " + reason);
        setStartState(start);
    }

    void ManipulationSetup::applyPlannerParameters(const Scene &scene)
    {
        for (const PlannerParam &param : scene.plannerParams)
        {
            if (!mopl_->params().hasParam(param.name))
            {
                std::vector<std::string> names;
                mopl_->params().getParamNames(names);
                std::string known;
                for (const std::string &name : names)
                    known += (known.empty() ? "" : ", ") + name;
                throw InputError(param.where,
                                 "unknown planner parameter '" + param.name + "' (known: " + known + ")");
            }
            bool accepted = false;
            std::string why;
            try
            {
                accepted = mopl_->params().setParam(param.name, param.value);
            }
            catch (const std::exception &e)  // OMPL's string conversion throws std::runtime_error
            {
                why = std::string(": ") + e.what();
            }
            if (!accepted)
                throw InputError(param.where, "bad value '" + param.value + "' for planner parameter '" +
                                                  param.name + "'" + why);
        }
    }

    ManipulationPath &ManipulationSetup::manipulationPath() const
    {
        auto *path = dynamic_cast<ManipulationPath *>(pdef_->getSolutionPath().get());
        if (!path)
            throw ompl::Exception("ManipulationSetup", "no manipulation path has been found");
        return *path;
    }
}  // namespace ompl_mm
