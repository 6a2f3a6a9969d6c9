/* Executing a MOPL plan in ODE: the robot driven along the planned motion, the objects moving as
   physics moves them. */
#pragma once

#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mmphys/simulation/MotionExecution.h"

#include <vector>

namespace ompl_mmphys
{
    /** Where the simulation put an object after a push or a place, settled, against the plan. */
    struct Checkpoint
    {
        std::size_t state{0};                                       ///< the path state the plan reaches there
        unsigned int object{0};                                     ///< the object pushed or placed
        ompl_mm::PrimitiveKind kind{ompl_mm::PrimitiveKind::Push};  ///< Push, or Transfer for a place
        ompl_mm::ObjectPose simulated;                              ///< its simulated pose
    };

    /** A plan as executed in the simulation. */
    struct SimulatedPlan
    {
        /** Per path state, every object's simulated pose when the robot reached it (at the last,
            after the final settling: finalPoses). */
        std::vector<std::vector<ompl_mm::ObjectPose>> statePoses;
        std::vector<Checkpoint> checkpoints;          ///< after every push and every place
        std::vector<ompl_mm::ObjectPose> finalPoses;  ///< after the final settling
        std::vector<double> finalTilts;               ///< radians from upright, per object
        /** The tool point at every step, with one move per segment and per settling (the average
            force the robot exerted on the objects): for the trajectory metrics. */
        ompl_phys::RobotTrajectory tool;
        double simulatedSeconds{0.0};  ///< the plan's duration, settling included
    };

    /** Executes path in a PlanWorld of its space's model, starting from its first state (the
        robot and the objects where that state puts them, at rest), as MotionExecution drives it
        (the robot's joints along the straight lines between the states, an object held from the
        start of its pickup or transfer until they end, the world settling after every push and
        place), everything else free, and a last settling at the end. The path's labels say what
        each segment does.
        Deterministic: the same path and settings give the same numbers.
        @throws ompl::Exception for an empty path or settings that are not positive. */
    SimulatedPlan simulatePlan(const ompl_mm::ManipulationPath &path,
                               const SimulationSettings &settings = {});
}  // namespace ompl_mmphys
