#pragma once

#include "ompl_phys/knowledge/Violation.h"
#include "ompl_phys/scene/PhysicsScene.h"
#include "ompl_phys/world/BodyState.h"

#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO3StateSpace.h>

namespace ompl_phys
{
    /** The state space of a physics scene: for every moving body (robot first, then the movable
        bodies in scene order) its position, orientation, linear and angular velocity, as OMPL
        components (RealVector 3, SO3, RealVector 3, RealVector 3), all in the world frame. A state
        also carries the violation found while simulating into it, so the validity checker can
        reject states the propagator reached by breaking a rule mid-step. Distances weigh the
        robot's position most, then the bodies' positions, then velocities and orientations
        (weights below). Bounds come from the scene's planning limits: x and y from the robot's or
        the bodies' region, z from 1 m below the floor to 2 m above it, velocities from the speed
        limits. */
    class PhysicsStateSpace : public ompl::base::CompoundStateSpace
    {
    public:
        /** A compound state plus the violation met when simulating into it. */
        class StateType : public ompl::base::CompoundStateSpace::StateType
        {
        public:
            Violation violation{Violation::None};  ///< set by the propagator; None for written states
        };

        /** Weight of the robot's position in distances; the other weights are relative to it. */
        static constexpr double ROBOT_WEIGHT = 1.0;
        /** Weight of each movable body's position. */
        static constexpr double BODY_WEIGHT = 0.3;
        /** Weight of the position (m) inside one body's component; the three below weigh the
            body's orientation and velocities. */
        static constexpr double POSITION_WEIGHT = 1.0;
        static constexpr double ORIENTATION_WEIGHT = 0.05;       ///< of the orientation distance, rad
        static constexpr double LINEAR_VELOCITY_WEIGHT = 0.1;    ///< of the linear velocity distance, m/s
        static constexpr double ANGULAR_VELOCITY_WEIGHT = 0.01;  ///< of the angular velocity distance, rad/s

        /** One component per moving body: the robot, then the movable bodies in scene order. Shares
            scene, which it keeps alive.
            @throws ompl::Exception when scene is null. */
        explicit PhysicsStateSpace(PhysicsScenePtr scene);

        /** The robot plus the movable bodies: one component each. */
        std::size_t movingBodyCount() const { return getSubspaceCount(); }

        /** The bodies of state; states is resized to movingBodyCount(). */
        void readState(const ompl::base::State *state, BodyStates &states) const;
        /** Writes states into state and clears its violation (Violation::None).
            @throws std::out_of_range when states has fewer than movingBodyCount() entries. */
        void writeState(const BodyStates &states, ompl::base::State *state) const;

        /** Robot centre on the floor (world x, y, m). */
        Eigen::Vector2d robotPosition(const ompl::base::State *state) const;

        /** The scene the space was built from. */
        const PhysicsScene &scene() const { return *scene_; }

        /** OMPL's hook: a new StateType, its violation None. */
        ompl::base::State *allocState() const override;
        /** OMPL's hook: frees a state from allocState(). */
        void freeState(ompl::base::State *state) const override;
        /** OMPL's hook: copies the components and the violation. */
        void copyState(ompl::base::State *destination, const ompl::base::State *source) const override;
        /** OMPL's hook: a PhysicsStateSampler, which needs this space to outlive it. */
        ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;

    private:
        PhysicsScenePtr scene_;
    };
}  // namespace ompl_phys
