/* Executing labelled robot motions in a PlanWorld: the rules that the check of a whole plan and the
   simulation of one push while planning share, so that both move the robot and the objects alike. */
#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"
#include "ompl_mm/primitives/Trajectory.h"
#include "ompl_mmphys/world/PlanWorld.h"
#include "ompl_phys/metrics/TrajectoryMetrics.h"

#include <cstddef>
#include <vector>

namespace ompl_mmphys
{
    /** How a plan is executed. Joints move at most at the smaller of jointSpeed and their URDF
        velocity limit, and accelerate at most at jointAcceleration; pushes, pickups and transfers go
        at manipulationSpeedFactor of that speed. */
    struct SimulationSettings
    {
        double timeStep{0.004};               ///< ODE step, seconds
        double jointSpeed{0.5};               ///< m/s or rad/s
        double jointAcceleration{1.0};        ///< m/s² or rad/s²
        double manipulationSpeedFactor{1.0};  ///< share of the speed for segments that move an object
        /** simulated after a push, after a place and at the end, robot still, s: at most, since
            settling ends once the free objects have been at rest (below 1 mm/s and 0.01 rad/s)
            for 10 steps */
        double settleTime{0.5};
        WorldSettings world;  ///< gravity, friction of the robot and obstacles, ODE
    };

    /** Checks that settings' times, speeds and accelerations are positive (the settling time 0 or
        more). @throws ompl::Exception naming `who` and the setting otherwise. */
    void checkSettings(const SimulationSettings &settings, const char *who);

    /** The poses of every object in state. */
    std::vector<ompl_mm::ObjectPose> objectPoses(const ompl_mm::ManipulationStateSpace &space,
                                                 const ompl::base::State *state);

    /** What an execution reports as it goes; each hook does nothing unless overridden. */
    class ExecutionObserver
    {
    public:
        /** Observers are used through this base. */
        virtual ~ExecutionObserver() = default;
        /** After every world step, the robot having been driven to joint values q. */
        virtual void stepped(const double *q) { static_cast<void>(q); }
        /** The robot reached waypoint (and the world settled, if it settles there). */
        virtual void reached(std::size_t waypoint) { static_cast<void>(waypoint); }
        /** At waypoint, a push of object or its place (kind Push or Transfer) has ended and the world
            has settled. */
        virtual void settled(std::size_t waypoint, unsigned int object, ompl_mm::PrimitiveKind kind)
        {
            static_cast<void>(waypoint);
            static_cast<void>(object);
            static_cast<void>(kind);
        }
        /** A motion or a settling ended: its steps and the average force the robot exerted on the
            objects over them. */
        virtual void moved(const ompl_phys::RobotMove &move) { static_cast<void>(move); }
    };

    /** Drives a PlanWorld's robot along labelled waypoints as a position-controlled robot would.
        Consecutive segments with the same label whose joint motions point the same way are one run:
        one trapezoidal profile (SegmentTiming, from rest to rest) through all their waypoints, so
        that splitting a straight motion into pieces does not change what happens. Transit runs go at
        full speed, the others at the manipulation speed factor. An object is held from the start of
        its pickup or transfer until the last of them ends (then released and left to settle); a
        push is computed with the pushed object isolated (PlanWorld::isolate) until the world has
        settled after its last segment. */
    class MotionExecution
    {
    public:
        /** Executes in world with settings; the robot's speed limits come from world's model.
            @pre world and settings outlive it. */
        MotionExecution(PlanWorld &world, const SimulationSettings &settings);

        /** Drives the robot through waypoints (joint values, one array per waypoint, the first
            where the robot is), segment i labelled labels[i], reporting to observer.
            @pre labels.size() + 1 == waypoints.size(). */
        void execute(const std::vector<const double *> &waypoints,
                     const std::vector<ompl_mm::SegmentLabel> &labels, ExecutionObserver &observer);
        /** Lets the world run with the robot still at joint values q for the settling time, or
            until the free objects have been at rest for 10 steps in a row, whichever comes first. */
        void settle(const double *q, ExecutionObserver &observer);

    private:
        /** The waypoint at which the run starting at `first` ends. */
        std::size_t runEnd(const std::vector<const double *> &waypoints,
                           const std::vector<ompl_mm::SegmentLabel> &labels, std::size_t first) const;
        /** Drives the robot from waypoint first to waypoint last in one run at speedFactor,
            reporting the waypoints in between as the robot passes them. */
        void drive(const std::vector<const double *> &waypoints, std::size_t first, std::size_t last,
                   double speedFactor, ExecutionObserver &observer);

        PlanWorld &world_;
        const SimulationSettings &settings_;
        unsigned int dof_;
        std::vector<double> speeds_;  ///< per joint, before the speed factor
    };
}  // namespace ompl_mmphys
