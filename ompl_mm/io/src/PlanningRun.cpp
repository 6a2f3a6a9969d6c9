#include "ompl_mm/io/PlanningRun.h"

#include "ompl_core/run/GlobalSeed.h"
#include "ompl_core/run/TimeLimit.h"
#include "ompl_mm/base/StepTermination.h"
#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/io/ManipulationRunResult.h"
#include "ompl_mm/setup/MoplRace.h"

#include <ompl/util/Console.h>

#include <chrono>

namespace ompl_mm
{
    namespace
    {
        /** Makes setup's motion checks stop at condition while scope lives (when its validator is
            a ManipulationMotionValidator). */
        void boundChecks(ManipulationSetup &setup, const ompl::base::PlannerTerminationCondition &condition,
                         std::optional<ManipulationMotionValidator::TerminationScope> &scope)
        {
            if (auto validator = std::dynamic_pointer_cast<ManipulationMotionValidator>(
                    setup.getSpaceInformation()->getMotionValidator()))
                scope.emplace(*validator, condition);
        }
    }  // namespace

    PlanningRun::PlanningRun(const Scene &scene, PlanningRequest request, double loadSeconds,
                             const PrimitiveFactory &factory)
        : SetupRun(std::move(request), loadSeconds)
    {
        if (request_.planner.empty())
            request_.planner = scene.planner;
        ompl_core::reseedOmpl(request_.seed);
        setup_ = std::make_unique<ManipulationSetup>(scene, factory);
        if (setup_->goalFault())  // the scene is the run's input: an impossible goal is an input error
            throw *setup_->goalFault();
        if (request_.planner != scene.planner)
            setup_->selectPlanner(request_.planner);
        setup_->applyParameters(request_.parameters);
        if (const std::shared_ptr<MOPL> mopl = setup_->mopl())
            mopl->setSeed(static_cast<std::uint_fast32_t>(request_.seed));
        if (request_.threads < 1 || request_.threads > MoplRace::MAX_SEARCHES)
            throw ompl_core::InputError("threads must be 1 to " + std::to_string(MoplRace::MAX_SEARCHES) +
                                        ", got " + std::to_string(request_.threads));
        if (request_.threads > 1 && !setup_->mopl())
            throw ompl_core::InputError("threads above 1 race MOPL searches; planner '" + request_.planner +
                                        "' plans in one thread");
        for (unsigned int index = 1; index < request_.threads; ++index)
        {
            auto rival = std::make_unique<ManipulationSetup>(scene, factory);
            if (request_.planner != scene.planner)
                rival->selectPlanner(request_.planner);
            rival->applyParameters(request_.parameters);
            rival->mopl()->setSeed(MoplRace::seedOf(request_.seed, index));
            rivals_.push_back(std::move(rival));
        }
    }

    double PlanningRun::timeLimit() const
    {
        return request_.timeLimit > 0.0 ? request_.timeLimit : setup_->model()->scene().timeLimit;
    }

    void PlanningRun::solve(const ompl::base::PlannerTerminationCondition &stop)
    {
        setup_->setup();
        ompl_core::reseedOmpl(request_.seed);  // as the benchmark tool does
        phases_.setup = phases_.lap();
        // MOPL polls the condition within every step, and the motion validator's checks stop at it
        // too (OMPL's planners call checkMotion between their polls, and one continuous check near
        // triangle meshes can take a tenth of a second). Here, not in ManipulationSetup::solve: this
        // condition is a time limit, while a library user's may count its evaluations (OMPL's
        // IterationTerminationCondition), which the checks' polls would use up.
        const ompl::base::PlannerTerminationCondition termination = ompl_core::timeLimitOr(timeLimit(), stop);
        {
            const StepTermination inner(termination);
            std::optional<ManipulationMotionValidator::TerminationScope> bounded;
            boundChecks(*setup_, inner.condition(), bounded);
            if (rivals_.empty())
                setup_->solve(termination);
            else
                race(termination);
        }
        phases_.solve = phases_.lap();
        if (solved())
        {
            pathValid_ = setup_->manipulationPath().check();
            if (!*pathValid_)
                OMPL_ERROR("PlanningRun: the solution failed OMPL's path re-check");
        }
    }

    void PlanningRun::race(const ompl::base::PlannerTerminationCondition &termination)
    {
        std::vector<ManipulationSetup *> setups{setup_.get()};
        std::vector<std::optional<ManipulationMotionValidator::TerminationScope>> bounded(rivals_.size());
        for (std::size_t k = 0; k < rivals_.size(); ++k)
        {
            setups.push_back(rivals_[k].get());
            boundChecks(*rivals_[k], termination, bounded[k]);
        }
        const auto start = std::chrono::steady_clock::now();
        const int winner = MoplRace::solve(setups, termination);
        raceSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (winner > 0)
            std::swap(setup_, rivals_[static_cast<std::size_t>(winner) - 1]);
    }

    double PlanningRun::planningTime() const
    {
        return rivals_.empty() ? setup_->getLastPlanComputationTime() : raceSeconds_;
    }

    bool PlanningRun::solved() const
    {
        return setup_->getProblemDefinition()->hasExactSolution();
    }

    ompl_core::RunResult PlanningRun::record() const
    {
        const ompl_core::RunDescription run{setup_->model()->scene().name, request_.planner, request_.seed,
                                            timeLimit()};
        ompl_core::RunResult result = manipulationRunResult(run, *setup_, pathValid_);
        result.time = planningTime();
        return withPhases(std::move(result));
    }
}  // namespace ompl_mm
