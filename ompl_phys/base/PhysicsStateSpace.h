/* The state space of a physics scene: for every moving body (robot first, then the movable bodies
   in scene order) its position, orientation, linear and angular velocity, as OMPL components
   (RealVector 3, SO3, RealVector 3, RealVector 3). A state also carries the violation found while
   simulating into it, so the validity checker can reject states the propagator reached by breaking
   a rule mid-step. Distances weigh the robot's position most, then the bodies' positions, then
   velocities and orientations (weights below). Bounds come from the scene's planning limits. */
#pragma once

#include "ompl_phys/knowledge/Violation.h"
#include "ompl_phys/scene/PhysicsScene.h"
#include "ompl_phys/world/BodyState.h"

#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO3StateSpace.h>

namespace ompl_phys
{
    class PhysicsStateSpace : public ompl::base::CompoundStateSpace
    {
    public:
        /** A compound state plus the violation met when simulating into it. */
        class StateType : public ompl::base::CompoundStateSpace::StateType
        {
        public:
            Violation violation{Violation::None};
        };

        /** Weight of the robot's position in distances; the other weights are relative to it. */
        static constexpr double ROBOT_WEIGHT = 1.0;
        /** Weight of each movable body's position. */
        static constexpr double BODY_WEIGHT = 0.3;
        /** Weights inside one body: position, orientation (rad), linear (m/s), angular (rad/s) velocity. */
        static constexpr double POSITION_WEIGHT = 1.0;
        static constexpr double ORIENTATION_WEIGHT = 0.05;
        static constexpr double LINEAR_VELOCITY_WEIGHT = 0.1;
        static constexpr double ANGULAR_VELOCITY_WEIGHT = 0.01;

        /** One component per moving body: the robot, then the movable bodies in scene order. The scene
            must outlive the space. */
        explicit PhysicsStateSpace(PhysicsScenePtr scene);

        std::size_t movingBodyCount() const { return getSubspaceCount(); }

        void readState(const ompl::base::State *state, BodyStates &states) const;
        void writeState(const BodyStates &states, ompl::base::State *state) const;

        /** Robot centre on the floor (x, y). */
        Eigen::Vector2d robotPosition(const ompl::base::State *state) const;

        const PhysicsScene &scene() const { return *scene_; }

        ompl::base::State *allocState() const override;
        void freeState(ompl::base::State *state) const override;
        void copyState(ompl::base::State *destination, const ompl::base::State *source) const override;
        ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;

    private:
        PhysicsScenePtr scene_;
    };
}  // namespace ompl_phys
