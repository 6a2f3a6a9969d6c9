#include "ompl_phys/io/PhysicsPlanningRun.h"

#include "ompl_core/run/GlobalSeed.h"
#include "ompl_core/run/TimeLimit.h"
#include "ompl_phys/io/PhysicsRunResult.h"

#include <ompl/util/Console.h>

namespace ompl_phys
{
    PhysicsPlanningRun::PhysicsPlanningRun(const PhysicsScene &scene, PhysicsPlanningRequest request,
                                           double loadSeconds)
        : SetupRun(std::move(request), loadSeconds)
    {
        ompl_core::reseedOmpl(request_.seed);
        setup_ = std::make_unique<PhysicsSetup>(scene);
        if (setup_->goalFault())  // the scene is the run's input: an impossible goal is an input error
            throw *setup_->goalFault();
        setup_->setPlannerByName(request_.planner);
        ompl_core::applyParameters(*setup_->getPlanner(), request_.parameters);
    }

    double PhysicsPlanningRun::timeLimit() const
    {
        return request_.timeLimit > 0.0 ? request_.timeLimit : setup_->scene().timeLimit;
    }

    void PhysicsPlanningRun::solve(const ompl::base::PlannerTerminationCondition &stop)
    {
        setup_->setup();
        ompl_core::reseedOmpl(request_.seed);  // as the benchmark tool does
        phases_.setup = phases_.lap();
        setup_->solve(ompl_core::timeLimitOr(timeLimit(), stop));
        phases_.solve = phases_.lap();
        if (solved())
        {
            simulated_ = simulatePath(*setup_, setup_->getSolutionPath());
            if (!simulated_->reachesGoal)
                OMPL_ERROR("PhysicsPlanningRun: the re-simulated solution does not reach the goal (%s)",
                           violationName(simulated_->violation));
        }
    }

    ompl_core::RunResult PhysicsPlanningRun::record() const
    {
        const ompl_core::RunDescription run{setup_->scene().name, request_.planner, request_.seed,
                                            timeLimit()};
        return withPhases(physicsRunResult(run, *setup_, simulated()));
    }
}  // namespace ompl_phys
