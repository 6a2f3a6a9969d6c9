#pragma once

#include <ompl/base/PlannerTerminationCondition.h>

#include <chrono>
#include <memory>

namespace ompl_mm
{
    /** A planner's termination condition as the inside of its steps polls it. A step of a
        manipulation planner can take long (a continuous motion check near triangle meshes,
        inverse kinematics with restarts, a walk of many pieces, a smoothing step), so the
        planner's time limit must reach into it; but a condition may count its evaluations
        (OMPL's IterationTerminationCondition counts each one as an iteration), so polling it
        within every step would change what it counts. This view of the condition evaluates the
        planner's condition only once `period` seconds of wall time have passed since the step
        began (startStep()) or since its own last evaluation, and stays true once that was true:
        a quick step costs no evaluation (a counted planner iteration stays one evaluation),
        while a slow one ends within about `period` of the condition becoming true. Its own
        polls cost a clock read. Copies share one state; not thread-safe. */
    class StepTermination
    {
    public:
        /** How often at most a step evaluates the planner's condition, seconds: every millisecond,
            well inside the 50 ms by which the apps must end after their limit. */
        static constexpr double DEFAULT_PERIOD = 1e-3;

        /** A view of ptc, evaluating it at most every period seconds (0: at every poll); the
            first step begins now. */
        explicit StepTermination(const ompl::base::PlannerTerminationCondition &ptc,
                                 double period = DEFAULT_PERIOD)
            : state_(std::make_shared<State>(ptc, period)),
              condition_([state = state_] { return state->poll(); })
        {
        }

        /** Begins a step, after the caller has evaluated the planner's condition itself: the view
            evaluates it next `period` from now. */
        void startStep() { state_->next = Clock::now() + state_->period; }

        /** The condition to pass into the step's loops and checks. */
        const ompl::base::PlannerTerminationCondition &condition() const { return condition_; }

    private:
        using Clock = std::chrono::steady_clock;

        struct State
        {
            State(const ompl::base::PlannerTerminationCondition &condition, double seconds)
                : ptc(condition),
                  period(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
                  next(Clock::now() + period)
            {
            }

            /** True once the planner's condition was true at an evaluation. */
            bool poll()
            {
                if (ended)
                    return true;
                const Clock::time_point now = Clock::now();
                if (now < next)
                    return false;
                next = now + period;
                ended = ptc();
                return ended;
            }

            ompl::base::PlannerTerminationCondition ptc;  ///< shares its state with the caller's
            Clock::duration period;
            Clock::time_point next;
            bool ended{false};
        };

        std::shared_ptr<State> state_;
        ompl::base::PlannerTerminationCondition condition_;
    };
}  // namespace ompl_mm
