#include "ompl_mm/setup/ManipulationSetup.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/run/InfeasibleGoal.h"
#include "ompl_mm/base/ManipulationStateSampler.h"
#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/setup/ProblemCheck.h"
#include "ompl_mm/setup/SceneRobot.h"

#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <algorithm>

namespace ompl_mm
{
    namespace
    {
        /** One of OMPL's planners on the setup, for tasks that need no manipulation: its uniform
            samples keep every object at its start pose, so that it grows transits (the motion
            validator rejects any other motion it tries). */
        template <class Planner>
        ompl::base::PlannerPtr robotOnly(ManipulationSetup &setup)
        {
            setup.getStateSpace()->setStateSamplerAllocator(
                [](const ompl::base::StateSpace *space) {
                    return std::make_shared<ManipulationStateSampler>(space->as<ManipulationStateSpace>(),
                                                                      true);
                });
            return std::make_shared<Planner>(setup.getSpaceInformation());
        }

        ManipulationModelPtr makeModel(const Scene &scene)
        {
            ManipulationSetup::plannerRegistry().require(scene.planner,
                                                         ompl_core::SourceLocation{scene.file, 0});
            SceneRobot loaded = loadSceneRobot(scene);
            return std::make_shared<ManipulationModel>(std::move(loaded.scene), std::move(loaded.robot));
        }
    }  // namespace

    ManipulationSetup::ManipulationSetup(const Scene &scene, const PrimitiveFactory &factory)
        : ompl::geometric::SimpleSetup(std::make_shared<ManipulationStateSpace>(makeModel(scene)))
    {
        space_ = std::static_pointer_cast<ManipulationStateSpace>(getStateSpace());
        model_ = space_->model();
        checker_ = std::make_shared<ManipulationValidityChecker>(si_);
        setStateValidityChecker(checker_);
        setStartFromScene(model_->scene());
        goal_ = std::make_shared<ManipulationGoal>(si_);
        setGoal(goal_);
        primitives_ = factory.build(scene.primitives, space_.get());
        for (const PrimitivePtr &primitive : primitives_)
            primitive->setStateValidityChecker(checker_);
        si_->setMotionValidator(std::make_shared<ManipulationMotionValidator>(si_, primitives_));
        try
        {
            ProblemCheck(*space_).checkGoal(getProblemDefinition()->getStartState(0), primitives_);
        }
        catch (const ompl_core::InputError &fault)
        {
            goalFault_ = fault;
        }
        setPlannerByName(scene.planner);
        applyParameters(scene.plannerParams);
    }

    ompl::base::PlannerStatus ManipulationSetup::solve(double time)
    {
        if (goalFault_ && getGoal() == goal_)
            return lastStatus_ = ompl_core::infeasibleGoal("ManipulationSetup", *goalFault_);
        return SimpleSetup::solve(time);
    }

    ompl::base::PlannerStatus ManipulationSetup::solve(const ompl::base::PlannerTerminationCondition &ptc)
    {
        if (goalFault_ && getGoal() == goal_)
            return lastStatus_ = ompl_core::infeasibleGoal("ManipulationSetup", *goalFault_);
        return SimpleSetup::solve(ptc);
    }

    void ManipulationSetup::applyParameters(const std::vector<ompl_core::ParameterSetting> &settings)
    {
        applyParameters(*planner_, settings);
    }

    void ManipulationSetup::applyParameters(ompl::base::Planner &planner,
                                            const std::vector<ompl_core::ParameterSetting> &settings)
    {
        ompl_core::applyParameters(planner, settings);
        auto *mopl = dynamic_cast<MOPL *>(&planner);
        if (!mopl || settings.empty())
            return;
        try
        {
            mopl->checkParameters();
        }
        catch (const ompl::Exception &e)
        {
            // the last of the settings the rule reads: the one that broke it
            auto broke = std::find_if(settings.rbegin(), settings.rend(),
                                      [](const ompl_core::ParameterSetting &setting)
                                      { return MOPL::checksParameter(setting.name); });
            throw ompl_core::InputError(broke != settings.rend() ? broke->where : settings.back().where,
                                        e.what());
        }
    }

    ompl_core::PlannerRegistry<ManipulationSetup> &ManipulationSetup::plannerRegistry()
    {
        static ompl_core::PlannerRegistry<ManipulationSetup> registry = []
        {
            ompl_core::PlannerRegistry<ManipulationSetup> planners;
            planners.add("mopl", "MOPL, the multi-modal path planner",
                         [](ManipulationSetup &setup)
                         { return std::make_shared<MOPL>(setup.getSpaceInformation(), setup.primitives()); });
            planners.add("rrtconnect",
                         "OMPL's RRTConnect, moving the robot alone (objects stay where they start)",
                         robotOnly<ompl::geometric::RRTConnect>);
            planners.add("rrt", "OMPL's RRT, moving the robot alone (objects stay where they start)",
                         robotOnly<ompl::geometric::RRT>);
            planners.add("est", "OMPL's EST, moving the robot alone (objects stay where they start)",
                         robotOnly<ompl::geometric::EST>);
            return planners;
        }();
        return registry;
    }

    void ManipulationSetup::setPlannerByName(const std::string &name)
    {
        setPlanner(plannerRegistry().make(name, *this));
    }

    void ManipulationSetup::selectPlanner(const std::string &name)
    {
        setPlannerByName(name);
        std::vector<ompl_core::ParameterSetting> declared;
        for (const ompl_core::ParameterSetting &setting : model_->scene().plannerParams)
            if (planner_->params().hasParam(setting.name))
                declared.push_back(setting);
        applyParameters(declared);
    }

    std::shared_ptr<MOPL> ManipulationSetup::mopl() const
    {
        return std::dynamic_pointer_cast<MOPL>(planner_);
    }

    void ManipulationSetup::setStartFromScene(const Scene &scene)
    {
        const RobotModel &robot = model_->robot();
        if (scene.robotStart.size() != robot.dof())
            throw ompl_core::InputError(scene.robotStartWhere,
                                        "start has " + std::to_string(scene.robotStart.size()) +
                                            " joint values but robot '" + robot.name() + "' has " +
                                            std::to_string(robot.dof()) + " moving joints (" +
                                            robot.variableNames() + ")");
        ompl::base::ScopedState<> start(space_);
        std::copy(scene.robotStart.begin(), scene.robotStart.end(), space_->robotValues(start.get()));
        for (unsigned int i = 0; i < model_->objectCount(); ++i)
        {
            const MovableObject &object = scene.objects[i];
            if (model_->scene().restingSurface(object.start.position) < 0)
                throw ompl_core::InputError(object.where,
                                            "object '" + object.name + "' starts on no support surface");
            space_->setObjectPose(start.get(), i, object.start);
        }
        const std::string reason = checker_->explain(start.get());
        if (!reason.empty())
            ProblemCheck(*space_).rejectStart(start.get(), reason);
        setStartState(start);
    }

    ManipulationPath &ManipulationSetup::manipulationPath() const
    {
        const ompl::base::PathPtr solution = pdef_->getSolutionPath();
        if (auto *path = dynamic_cast<ManipulationPath *>(solution.get()))
            return *path;
        auto *geometric = dynamic_cast<ompl::geometric::PathGeometric *>(solution.get());
        if (!geometric)
            throw ompl::Exception("ManipulationSetup", "no manipulation path has been found");
        // another planner's path: the same states, labelled from their motions when asked
        auto path = std::make_shared<ManipulationPath>(si_);
        for (const ompl::base::State *state : geometric->getStates())
            path->ompl::geometric::PathGeometric::append(state);
        const ompl::base::PlannerSolution found = pdef_->getSolutions().front();
        pdef_->clearSolutionPaths();
        pdef_->addSolutionPath(path, found.approximate_, found.difference_, found.plannerName_);
        return *path;
    }

    ManipulationSimplifier::Outcome ManipulationSetup::smoothSolution(unsigned int attempts,
                                                                      std::uint_fast32_t seed)
    {
        ompl::RNG rng(seed);
        return ManipulationSimplifier(si_).simplify(manipulationPath(), attempts, rng, goal_.get());
    }
}  // namespace ompl_mm
