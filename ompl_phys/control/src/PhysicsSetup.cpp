#include "ompl_phys/control/PhysicsSetup.h"

#include "ompl_mm/scene/InputError.h"
#include "ompl_phys/base/PhysicsGoal.h"
#include "ompl_phys/base/PhysicsValidityChecker.h"
#include "ompl_phys/base/RobotProjection.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/control/planners/est/EST.h>
#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/pdst/PDST.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/sst/SST.h>
#include <ompl/control/planners/syclop/SyclopEST.h>
#include <ompl/control/planners/syclop/SyclopRRT.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

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

        /** A planner of type P with the given goal bias. */
        template <typename P>
        ompl::base::PlannerPtr withGoalBias(const oc::SpaceInformationPtr &si, double bias)
        {
            auto planner = std::make_shared<P>(si);
            planner->setGoalBias(bias);
            return planner;
        }

        std::string joinNames(const std::vector<std::string> &names)
        {
            std::string joined;
            for (const std::string &name : names)
                joined += (joined.empty() ? "" : ", ") + name;
            return joined;
        }
    }  // namespace

    PhysicsSetup::PhysicsSetup(const PhysicsScene &scene)
        : PhysicsSetup(std::make_unique<PhysicsWorld>(scene))
    {
    }

    oc::SpaceInformationPtr PhysicsSetup::spaceInformation(const PhysicsWorld &world)
    {
        auto space = std::make_shared<PhysicsStateSpace>(world.scene());
        space->registerDefaultProjection(std::make_shared<RobotProjection>(space.get()));
        return std::make_shared<oc::SpaceInformation>(space,
                                                      forceSpace(space, world.scene().limits.maxForce));
    }

    PhysicsSetup::PhysicsSetup(std::unique_ptr<PhysicsWorld> world)
        : oc::SimpleSetup(spaceInformation(*world)),
          world_(std::move(world)),
          knowledge_(std::make_unique<ManipulationKnowledge>(world_->scene())),
          space_(std::static_pointer_cast<PhysicsStateSpace>(si_->getStateSpace()))
    {
        const PlanningLimits &limits = world_->scene().limits;
        si_->setPropagationStepSize(limits.stepSize);
        si_->setMinMaxControlDuration(limits.minControlSteps, limits.maxControlSteps);
        si_->setStateValidityChecker(std::make_shared<PhysicsValidityChecker>(si_, *knowledge_));
        propagator_ = std::make_shared<PhysicsStatePropagator>(si_, *world_, *knowledge_);
        si_->setStatePropagator(propagator_);
        decomposition_ = std::make_shared<RobotGridDecomposition>(*space_);

        checkStart();
        ompl::base::ScopedState<> start(space_);
        space_->writeState(world_->startStates(), start.get());
        setStartState(start);
        setGoal(std::make_shared<PhysicsGoal>(si_, *knowledge_, world_->startStates()));
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
                throw ompl_mm::InputError(
                    s.bodies[body].where,
                    "the robot starts touching '" + s.bodies[body].name + "', which it must not touch");
        const Violation violation = knowledge_->checkStates(start);
        if (violation != Violation::None)
            throw ompl_mm::InputError(s.robot.where,
                                      std::string("the start breaks a rule: ") + violationName(violation));
        if (depth > START_PENETRATION_TOLERANCE)
        {
            std::ostringstream message;
            message << "bodies overlap at the start (" << depth << " m deep)";
            throw ompl_mm::InputError(s.robot.where, message.str());
        }
        for (std::size_t body : knowledge_->fixedBodiesOnGoal())
            throw ompl_mm::InputError(s.goal.where, "the goal cannot be reached: fixed body '" +
                                                        s.bodies[body].name + "' covers its centre");
    }

    const std::vector<std::string> &PhysicsSetup::plannerNames()
    {
        static const std::vector<std::string> names = {"rrt",       "est",  "kpiece", "sycloprrt",
                                                       "syclopest", "pdst", "sst"};
        return names;
    }

    void PhysicsSetup::setPlannerByName(const std::string &name)
    {
        const double bias = world_->scene().limits.goalBias;
        if (name == "rrt")
            setPlanner(withGoalBias<oc::RRT>(si_, bias));
        else if (name == "est")
            setPlanner(withGoalBias<oc::EST>(si_, bias));
        else if (name == "kpiece")
            setPlanner(withGoalBias<oc::KPIECE1>(si_, bias));
        else if (name == "sycloprrt")
            setPlanner(std::make_shared<oc::SyclopRRT>(si_, decomposition_));
        else if (name == "syclopest")
            setPlanner(std::make_shared<oc::SyclopEST>(si_, decomposition_));
        else if (name == "pdst")
            setPlanner(withGoalBias<oc::PDST>(si_, bias));
        else if (name == "sst")
        {
            // SST optimises until its time is up unless its objective is satisfied: any solution is
            // good enough here, as for the other planners
            auto objective = std::make_shared<ompl::base::PathLengthOptimizationObjective>(si_);
            objective->setCostThreshold(objective->infiniteCost());
            pdef_->setOptimizationObjective(objective);
            setPlanner(withGoalBias<oc::SST>(si_, bias));
        }
        else
            throw ompl::Exception("PhysicsSetup", "unknown planner '" + name + "', expected one of " +
                                                      joinNames(plannerNames()));
    }

    bool PhysicsSetup::haveExactSolution() const
    {
        return pdef_->hasExactSolution();
    }
}  // namespace ompl_phys
