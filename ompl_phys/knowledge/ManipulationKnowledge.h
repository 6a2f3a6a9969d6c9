#pragma once

#include "ompl_phys/knowledge/Violation.h"
#include "ompl_phys/scene/PhysicsScene.h"
#include "ompl_phys/world/BodyState.h"

#include <vector>

namespace ompl_phys
{
    /** The manipulation knowledge of the ontological physics-based planner (Muhayyuddin, Akbari,
        Rosell, "Ontological physics-based motion planning for manipulation", ETFA 2015; benchmarked
        in "Physics-based motion planning: evaluation criteria and benchmarking", ROBOT 2015) as
        rules over simulated states. Each body is fixed, freely manipulatable or
        constraint-oriented:
        - the robot must not touch a fixed body;
        - the robot may touch a constraint-oriented body only while its centre lies in the body's
          push region (a strip along the push axis), and the body may only slide along that axis
          without turning;
        - free bodies may be touched and moved in any way.

        It also reasons about the goal: which bodies occupy the goal region, and where a goal state
        puts them so the robot fits there (constraint-oriented bodies slide along their axis, free
        bodies move straight away from the goal). The scene's planning limits (regions, speeds) and
        finiteness are checked with the same vocabulary of violations.

        Immutable after construction, so one knowledge may be shared by several objects and
        threads. Moving bodies are numbered as in BodyState: the robot (0), then the movable bodies
        in scene order; BodyStates given to it hold every moving body. */
    class ManipulationKnowledge
    {
    public:
        /** Largest lean of a movable box's, cylinder's or prism's up axis from vertical, radians
            (15°): a pushed cube tilts a few degrees; beyond this it is falling over. */
        static constexpr double TIP_TOLERANCE = 0.2617993877991494;
        /** Deepest penetration between two bodies (the robot, movable and fixed bodies, the floor)
            that a simulated state may show, metres: ODE's soft contacts rest about its 1 mm
            surface layer deep; deeper, a body is sinking into another. */
        static constexpr double SINK_TOLERANCE = 0.005;

        /** Shares scene, which it keeps alive.
            @throws ompl::Exception when scene is null. */
        explicit ManipulationKnowledge(PhysicsScenePtr scene);

        /** Whether the robot, centred at robotCentre (world frame, m), may touch scene body `body`
            in state bodyState: never a fixed body, always a free one, and a constraint-oriented one
            only while the robot centre lies in its push strip (bodyState is used only then). */
        bool touchAllowed(std::size_t body, const Eigen::Vector3d &robotCentre,
                          const BodyState &bodyState) const;

        /** The first broken rule among the robot's touches (scene body indices) in states, or
            Violation::None. */
        Violation checkTouches(const std::vector<std::size_t> &touches, const BodyStates &states) const;

        /** Violation::SankIn when the deepest penetration a collision check found between two bodies
            (PhysicsWorld::deepestPenetration, metres) exceeds SINK_TOLERANCE, else Violation::None. */
        static Violation checkPenetration(double deepest);

        /** The first broken rule or limit of the states alone, or Violation::None: finiteness,
            regions, the robot overlapping a fixed body, speeds, constraint-oriented bodies on
            their axes, and movable bodies upright (TIP_TOLERANCE; spheres have no up). */
        Violation checkStates(const BodyStates &states) const;

        /** Moving bodies (indices >= 1) whose footprint overlaps the robot standing anywhere in the
            goal disc, in states. */
        std::vector<std::size_t> goalOccupants(const BodyStates &states) const;

        /** Fixed scene bodies whose footprint overlaps the goal centre with the robot there: the goal
            cannot be reached. */
        std::vector<std::size_t> fixedBodiesOnGoal() const;

        /** Moves the goal occupants of states out of the way of a robot at robotGoal (on the goal
            disc, world frame): constraint-oriented bodies along their push axis (to the nearer
            free side), free bodies straight away from robotGoal, each with clearance metres to
            spare. Only positions change; a body that cannot be cleared within the body region
            stays where it is. */
        void clearGoal(BodyStates &states, const Eigen::Vector2d &robotGoal, double clearance) const;

    private:
        /** Where a fixed body stands on the floor. */
        struct FixedFootprint
        {
            std::size_t body;
            Eigen::Vector2d position;
            double yaw;
        };

        /** A constraint-oriented body's start orientation and push axis on the floor (unused for free
         * bodies). */
        struct StartAxis
        {
            Eigen::Quaterniond orientation;
            Eigen::Vector2d axis;
        };

        PhysicsScenePtr scene_;
        std::vector<FixedFootprint> fixed_;
        std::vector<std::size_t> movable_;      ///< scene body of each moving body after the robot
        std::vector<std::size_t> movingIndex_;  ///< moving index of each scene body (0: fixed)
        std::vector<StartAxis> startAxes_;      ///< per movable body
    };
}  // namespace ompl_phys
