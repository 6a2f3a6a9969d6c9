/* Whether a MOPL plan holds in physics: its simulated outcome judged against the plan and the goal. */
#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"
#include "ompl_mmphys/simulation/PlanSimulation.h"

#include <string>
#include <vector>

namespace ompl_mmphys
{
    /** One degree, radians. */
    constexpr double DEGREE = 0.017453292519943295;

    /** How far the simulated outcome may stray from the plan for the plan to count as confirmed. */
    struct CheckTolerances
    {
        double position{0.02};       ///< metres, distance of an object's base centre from its planned one
        double yaw{5.0 * DEGREE};    ///< radians, of an object whose yaw matters (not a cylinder or sphere)
        double tilt{20.0 * DEGREE};  ///< radians from upright beyond which an object has tipped over
    };

    /** The simulated outcome of one object. */
    struct ObjectCheck
    {
        std::string name;                          ///< the object's name
        double positionError{0.0};                 ///< metres from its planned end pose
        double yawError{0.0};                      ///< radians; 0 for an object whose yaw does not matter
        bool tipped{false};                        ///< ends tilted beyond the tolerance
        bool offSurface{false};                    ///< ends resting on no support surface
        double worstPositionErrorAfterMoves{0.0};  ///< metres, after any of its push runs and places
        double worstYawErrorAfterMoves{0.0};       ///< radians, likewise
    };

    /** A plan's physics check: confirmed when every object ends within the tolerances of its
        planned end pose, upright, and the goal holds in the simulated end state. */
    struct PhysicsCheck
    {
        bool confirmed{false};                 ///< within the tolerances and the goal holds
        bool goalHolds{false};                 ///< the scene's goal, judged on the simulated end poses
        double maxPositionError{0.0};          ///< metres, largest end error over the objects
        double maxYawError{0.0};               ///< radians, likewise
        std::vector<ObjectCheck> objects;      ///< in scene order
        ompl_phys::TrajectoryMetrics metrics;  ///< of the tool point, with the robot's contact forces
        double simulatedSeconds{0.0};          ///< the plan's simulated duration
        double wallSeconds{0.0};               ///< how long the check took, seconds
        SimulatedPlan simulation;              ///< what the simulation gave
    };

    /** Simulates path (simulatePlan) and judges it against its own end state, the tolerances and
        the goal of setup (the setup path was planned with). An object rests where the simulation
        leaves it when its base lies within a centimetre of a support surface that covers it.
        @throws as simulatePlan. */
    PhysicsCheck checkPlan(const ompl_mm::ManipulationSetup &setup, const ompl_mm::ManipulationPath &path,
                           const SimulationSettings &settings = {}, const CheckTolerances &tolerances = {});

    /** The difference of two yaws wrapped to [0, pi], radians. */
    double yawDifference(double a, double b);
}  // namespace ompl_mmphys
