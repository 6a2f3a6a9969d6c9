#include "ompl_phys/control/PathSimulation.h"

#include <ompl/base/ScopedState.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/Exception.h>

#include <cmath>

namespace ompl_phys
{
    namespace
    {
        /** Durations are whole multiples of the step up to this relative round-off. */
        constexpr double STEP_ROUNDING = 1e-6;
    }  // namespace

    SimulatedPath simulatePath(const PhysicsSetup &setup, const ompl::control::PathControl &path)
    {
        const auto &si = setup.getSpaceInformation();
        const PhysicsStateSpace &space = setup.physicsSpace();
        const double step = si->getPropagationStepSize();
        SimulatedPath simulated;
        simulated.robot.stepDuration = step;
        if (path.getStateCount() == 0)
            return simulated;

        // checking a plan is not searching for one: the propagator's counts stay the search's
        const PhysicsStatePropagator::Counters searched = setup.propagator().counters();
        ompl::base::ScopedState<> current(si->getStateSpace(), path.getState(0));
        ompl::base::ScopedState<> next(si->getStateSpace());
        auto record = [&](const ompl::base::State *state)
        {
            simulated.states.emplace_back();
            space.readState(state, simulated.states.back());
            simulated.robot.positions.push_back(simulated.states.back()[0].position);
        };
        record(current.get());
        for (std::size_t i = 0; i < path.getControlCount() && simulated.violation == Violation::None; ++i)
        {
            const double exactSteps = path.getControlDuration(i) / step;
            const double steps = std::round(exactSteps);
            if (steps < 1.0 || std::abs(exactSteps - steps) > STEP_ROUNDING * exactSteps)
                throw ompl::Exception("simulatePath", "control " + std::to_string(i) + " lasts " +
                                                          std::to_string(path.getControlDuration(i)) +
                                                          " s, not a whole number of steps");
            RobotMove move;
            Eigen::Vector2d impulse = Eigen::Vector2d::Zero();
            for (std::size_t k = 0; k < static_cast<std::size_t>(steps); ++k)
            {
                si->getStatePropagator()->propagate(current.get(), path.getControl(i), step, next.get());
                impulse += setup.propagator().lastImpulse();
                record(next.get());
                ++move.steps;
                current = next;
                simulated.violation = next->as<PhysicsStateSpace::StateType>()->violation;
                if (simulated.violation == Violation::None)
                    simulated.violation = setup.knowledge().checkStates(simulated.states.back());
                if (simulated.violation != Violation::None)
                    break;
            }
            // the force the drive applied on average, which the speed limit may have held back
            const Eigen::Vector2d force = impulse / (static_cast<double>(move.steps) * step);
            move.force = Eigen::Vector3d(force.x(), force.y(), 0.0);
            simulated.robot.moves.push_back(move);
        }
        simulated.metrics = computeTrajectoryMetrics(simulated.robot);
        simulated.reachesGoal = simulated.violation == Violation::None &&
                                setup.getProblemDefinition()->getGoal()->isSatisfied(current.get());
        setup.propagator().restoreCounters(searched);
        return simulated;
    }
}  // namespace ompl_phys
