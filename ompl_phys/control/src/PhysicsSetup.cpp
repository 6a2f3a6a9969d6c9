#include "ompl_phys/control/PhysicsSetup.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_core/run/InfeasibleGoal.h"
#include "ompl_core/run/ParameterSetting.h"
#include "ompl_phys/base/PhysicsGoal.h"
#include "ompl_phys/base/PhysicsValidityChecker.h"
#include "ompl_phys/base/RobotProjection.h"
#include "ompl_phys/control/PDSTPlanner.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/control/planners/est/EST.h>
#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/sst/SST.h>
#include <ompl/control/planners/syclop/SyclopEST.h>
#include <ompl/control/planners/syclop/SyclopRRT.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <iomanip>
#include <locale>
#include <sstream>

namespace ompl_phys
{
    namespace oc = ompl::control;

    namespace
    {
        /** Bodies may start this deep in each other (soft contacts settle there), m. */
        constexpr double START_PENETRATION_TOLERANCE = 0.002;

        oc::ControlSpacePtr forceSpace(const ompl::base::StateSpacePtr &space, double maxForce)
        {
            auto controls = std::make_shared<oc::RealVectorControlSpace>(space, 2);
            ompl::base::RealVectorBounds bounds(2);
            bounds.setLow(-maxForce);
            bounds.setHigh(maxForce);
            controls->setBounds(bounds);
            return controls;
        }

    }  // namespace

    PhysicsSetup::PhysicsSetup(const PhysicsScene &scene)
        : PhysicsSetup(std::make_shared<const PhysicsScene>(scene))
    {
    }

    PhysicsSetup::PhysicsSetup(PhysicsScenePtr scene)
        : PhysicsSetup(std::make_shared<PhysicsWorld>(std::move(scene)))
    {
    }

    oc::SpaceInformationPtr PhysicsSetup::spaceInformation(const PhysicsWorld &world)
    {
        auto space = std::make_shared<PhysicsStateSpace>(world.scenePtr());
        space->registerDefaultProjection(std::make_shared<RobotProjection>(space.get()));
        return std::make_shared<oc::SpaceInformation>(space,
                                                      forceSpace(space, world.scene().limits.maxForce));
    }

    PhysicsSetup::PhysicsSetup(std::shared_ptr<PhysicsWorld> world)
        : oc::SimpleSetup(spaceInformation(*world)),
          world_(std::move(world)),
          knowledge_(std::make_shared<const ManipulationKnowledge>(world_->scenePtr())),
          space_(std::static_pointer_cast<PhysicsStateSpace>(si_->getStateSpace()))
    {
        const PlanningLimits &limits = world_->scene().limits;
        si_->setPropagationStepSize(limits.stepSize);
        si_->setMinMaxControlDuration(limits.minControlSteps, limits.maxControlSteps);
        si_->setStateValidityChecker(std::make_shared<PhysicsValidityChecker>(si_, knowledge_));
        propagator_ = std::make_shared<PhysicsStatePropagator>(si_, world_, knowledge_);
        si_->setStatePropagator(propagator_);
        decomposition_ = std::make_shared<RobotGridDecomposition>(space_);

        checkStart();
        ompl::base::ScopedState<> start(space_);
        space_->writeState(world_->startStates(), start.get());
        setStartState(start);
        goal_ = std::make_shared<PhysicsGoal>(si_, knowledge_, world_->startStates());
        setGoal(goal_);
        goalFault_ = findGoalFault();
        setPlannerByName("kpiece");
    }

    void PhysicsSetup::checkStart() const
    {
        const PhysicsScene &s = world_->scene();
        const BodyStates start = world_->startStates();
        world_->setStates(start);
        const double depth = world_->detectContacts();
        // touches first: their message names the body
        for (std::size_t body : world_->touches())
            if (knowledge_->checkTouches({body}, start) != Violation::None)
                throw ompl_core::InputError(
                    s.bodies[body].where,
                    "the robot starts touching '" + s.bodies[body].name + "', which it must not touch");
        const Violation violation = knowledge_->checkStates(start);
        if (violation != Violation::None)
            throw ompl_core::InputError(s.robot.where,
                                        std::string("the start breaks a rule: ") + violationName(violation));
        if (depth > START_PENETRATION_TOLERANCE)
        {
            std::ostringstream message;
            message << "bodies overlap at the start (" << depth << " m deep)";
            throw ompl_core::InputError(s.robot.where, message.str());
        }
    }

    std::optional<ompl_core::InputError> PhysicsSetup::findGoalFault() const
    {
        for (std::size_t body : knowledge_->fixedBodiesOnGoal())
            return ompl_core::InputError(world_->scene().goal.where,
                                         "the goal cannot be reached: fixed body '" +
                                             world_->scene().bodies[body].name + "' covers its centre");
        return std::nullopt;
    }

    ompl::base::PlannerStatus PhysicsSetup::solve(double time)
    {
        if (goalFault_ && getGoal() == goal_)
            return last_status_ = ompl_core::infeasibleGoal("PhysicsSetup", *goalFault_);
        return oc::SimpleSetup::solve(time);
    }

    ompl::base::PlannerStatus PhysicsSetup::solve(const ompl::base::PlannerTerminationCondition &ptc)
    {
        if (goalFault_ && getGoal() == goal_)
            return last_status_ = ompl_core::infeasibleGoal("PhysicsSetup", *goalFault_);
        return oc::SimpleSetup::solve(ptc);
    }

    ompl_core::PlannerRegistry<PhysicsSetup> &PhysicsSetup::plannerRegistry()
    {
        static ompl_core::PlannerRegistry<PhysicsSetup> registry = []
        {
            ompl_core::PlannerRegistry<PhysicsSetup> planners;
            planners.add("rrt", "control-based RRT",
                         [](PhysicsSetup &s) { return std::make_shared<oc::RRT>(s.getSpaceInformation()); });
            planners.add("est", "control-based EST",
                         [](PhysicsSetup &s) { return std::make_shared<oc::EST>(s.getSpaceInformation()); });
            planners.add("kpiece", "KPIECE1",
                         [](PhysicsSetup &s)
                         { return std::make_shared<oc::KPIECE1>(s.getSpaceInformation()); });
            planners.add(
                "sycloprrt", "SyCLoP with RRT on the robot grid",
                [](PhysicsSetup &s)
                { return std::make_shared<oc::SyclopRRT>(s.getSpaceInformation(), s.decomposition()); });
            planners.add(
                "syclopest", "SyCLoP with EST on the robot grid",
                [](PhysicsSetup &s)
                { return std::make_shared<oc::SyclopEST>(s.getSpaceInformation(), s.decomposition()); });
            planners.add("pdst", "PDST",
                         [](PhysicsSetup &s)
                         { return std::make_shared<PDSTPlanner>(s.getSpaceInformation()); });
            planners.add("sst", "SST, stopping at its first solution",
                         [](PhysicsSetup &s)
                         {
                             // SST optimises until its time is up unless its objective is satisfied:
                             // any solution is good enough here, as for the other planners
                             auto objective = std::make_shared<ompl::base::PathLengthOptimizationObjective>(
                                 s.getSpaceInformation());
                             objective->setCostThreshold(objective->infiniteCost());
                             s.getProblemDefinition()->setOptimizationObjective(objective);
                             return std::make_shared<oc::SST>(s.getSpaceInformation());
                         });
            return planners;
        }();
        return registry;
    }

    void PhysicsSetup::setPlannerByName(const std::string &name)
    {
        // a planner's objective (SST's) must not stay behind for the next planner
        pdef_->setOptimizationObjective(nullptr);
        ompl::base::PlannerPtr planner = plannerRegistry().make(name, *this);
        const PlanningLimits &limits = world_->scene().limits;
        if (planner->params().hasParam("goal_bias"))
            ompl_core::applyParameters(*planner,
                                       {{"goal_bias", ompl_core::exactText(limits.goalBias), limits.where}});
        setPlanner(planner);
    }

    bool PhysicsSetup::haveExactSolution() const
    {
        return pdef_->hasExactSolution();
    }
}  // namespace ompl_phys
