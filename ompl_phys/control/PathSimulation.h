#pragma once

#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/metrics/TrajectoryMetrics.h"

#include <ompl/control/PathControl.h>

namespace ompl_phys
{
    /** What the re-simulation of a control path found (simulatePath()). */
    struct SimulatedPath
    {
        std::vector<BodyStates> states;        ///< all moving bodies at every step, from the start
        RobotTrajectory robot;                 ///< robot centre at every step, and the moves
        Violation violation{Violation::None};  ///< first broken rule; the simulation stops there
        bool reachesGoal{false};               ///< no violation and the last state satisfies the goal
        TrajectoryMetrics metrics;             ///< action, power and smoothness of `robot`
    };

    /** Re-simulates a control path from its first state, one propagation step at a time, exactly as
        the planners propagated it: the states of every moving body at every step (for pictures and
        checks), the robot trajectory for the quality metrics, whether every step kept the rules,
        and whether the simulated end satisfies the goal. This is the independent check that a plan
        works: it uses only the path's controls and durations, not its stored states. It runs
        through the setup's propagator and world, and leaves the propagator's counters as the search left
        them (they count the search's propagations only); a path
        without states gives an empty result.
        @pre path was planned on setup (its states and controls belong to setup's spaces).
        @throws ompl::Exception when a control duration is not a whole number of steps. */
    SimulatedPath simulatePath(const PhysicsSetup &setup, const ompl::control::PathControl &path);
}  // namespace ompl_phys
