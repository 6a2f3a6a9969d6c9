#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/util/Exception.h>

#include "ompl_phys/base/PhysicsStateSampler.h"

namespace ompl_phys
{
    namespace ob = ompl::base;

    namespace
    {
        enum Component
        {
            POSITION = 0,
            ORIENTATION = 1,
            LINEAR_VELOCITY = 2,
            ANGULAR_VELOCITY = 3
        };

        /** How far below the floor and above it a body centre may be, m (loose: the floor holds bodies). */
        constexpr double Z_BELOW = 1.0;
        constexpr double Z_ABOVE = 2.0;

        ob::StateSpacePtr bodySpace(const std::string &name, const Eigen::AlignedBox2d &region,
                                    double maxSpeed, double maxAngularSpeed)
        {
            auto position = std::make_shared<ob::RealVectorStateSpace>(3);
            ob::RealVectorBounds positionBounds(3);
            positionBounds.setLow(0, region.min().x());
            positionBounds.setHigh(0, region.max().x());
            positionBounds.setLow(1, region.min().y());
            positionBounds.setHigh(1, region.max().y());
            positionBounds.setLow(2, -Z_BELOW);
            positionBounds.setHigh(2, Z_ABOVE);
            position->setBounds(positionBounds);
            auto linear = std::make_shared<ob::RealVectorStateSpace>(3);
            linear->setBounds(-maxSpeed, maxSpeed);
            auto angular = std::make_shared<ob::RealVectorStateSpace>(3);
            angular->setBounds(-maxAngularSpeed, maxAngularSpeed);

            auto body = std::make_shared<ob::CompoundStateSpace>();
            body->setName(name);
            body->addSubspace(position, PhysicsStateSpace::POSITION_WEIGHT);
            body->addSubspace(std::make_shared<ob::SO3StateSpace>(), PhysicsStateSpace::ORIENTATION_WEIGHT);
            body->addSubspace(linear, PhysicsStateSpace::LINEAR_VELOCITY_WEIGHT);
            body->addSubspace(angular, PhysicsStateSpace::ANGULAR_VELOCITY_WEIGHT);
            body->lock();
            return body;
        }
    }  // namespace

    PhysicsStateSpace::PhysicsStateSpace(PhysicsScenePtr scene) : scene_(std::move(scene))
    {
        if (!scene_)
            throw ompl::Exception("PhysicsStateSpace", "needs a scene, got none");
        setName("Physics" + getName());
        const PlanningLimits &limits = scene_->limits;
        addSubspace(
            bodySpace(scene_->robot.name, limits.robotRegion, limits.maxRobotSpeed, limits.maxAngularSpeed),
            ROBOT_WEIGHT);
        for (std::size_t index : scene_->movableBodies())
            addSubspace(bodySpace(scene_->bodies[index].name, limits.bodyRegion, limits.maxBodySpeed,
                                  limits.maxAngularSpeed),
                        BODY_WEIGHT);
        lock();
    }

    void PhysicsStateSpace::readState(const ob::State *state, BodyStates &states) const
    {
        const auto *compound = state->as<ob::CompoundState>();
        states.resize(getSubspaceCount());
        for (std::size_t i = 0; i < states.size(); ++i)
        {
            const auto *body = compound->as<ob::CompoundState>(i);
            const double *p = body->as<ob::RealVectorStateSpace::StateType>(POSITION)->values;
            const auto *q = body->as<ob::SO3StateSpace::StateType>(ORIENTATION);
            const double *v = body->as<ob::RealVectorStateSpace::StateType>(LINEAR_VELOCITY)->values;
            const double *w = body->as<ob::RealVectorStateSpace::StateType>(ANGULAR_VELOCITY)->values;
            states[i].position = Eigen::Vector3d(p[0], p[1], p[2]);
            states[i].orientation = Eigen::Quaterniond(q->w, q->x, q->y, q->z);
            states[i].linearVelocity = Eigen::Vector3d(v[0], v[1], v[2]);
            states[i].angularVelocity = Eigen::Vector3d(w[0], w[1], w[2]);
        }
    }

    void PhysicsStateSpace::writeState(const BodyStates &states, ob::State *state) const
    {
        auto *compound = state->as<ob::CompoundState>();
        for (std::size_t i = 0; i < getSubspaceCount(); ++i)
        {
            auto *body = compound->as<ob::CompoundState>(i);
            const BodyState &s = states.at(i);
            double *p = body->as<ob::RealVectorStateSpace::StateType>(POSITION)->values;
            auto *q = body->as<ob::SO3StateSpace::StateType>(ORIENTATION);
            double *v = body->as<ob::RealVectorStateSpace::StateType>(LINEAR_VELOCITY)->values;
            double *w = body->as<ob::RealVectorStateSpace::StateType>(ANGULAR_VELOCITY)->values;
            for (int k = 0; k < 3; ++k)
            {
                p[k] = s.position[k];
                v[k] = s.linearVelocity[k];
                w[k] = s.angularVelocity[k];
            }
            q->w = s.orientation.w();
            q->x = s.orientation.x();
            q->y = s.orientation.y();
            q->z = s.orientation.z();
        }
        state->as<StateType>()->violation = Violation::None;
    }

    Eigen::Vector2d PhysicsStateSpace::robotPosition(const ob::State *state) const
    {
        const double *p = state->as<ob::CompoundState>()
                              ->as<ob::CompoundState>(0)
                              ->as<ob::RealVectorStateSpace::StateType>(POSITION)
                              ->values;
        return {p[0], p[1]};
    }

    ob::State *PhysicsStateSpace::allocState() const
    {
        auto *state = new StateType();
        allocStateComponents(state);
        return state;
    }

    void PhysicsStateSpace::freeState(ob::State *state) const
    {
        auto *physics = static_cast<StateType *>(state);
        for (unsigned int i = 0; i < componentCount_; ++i)
            components_[i]->freeState(physics->components[i]);
        delete[] physics->components;
        delete physics;
    }

    void PhysicsStateSpace::copyState(ob::State *destination, const ob::State *source) const
    {
        CompoundStateSpace::copyState(destination, source);
        destination->as<StateType>()->violation = source->as<StateType>()->violation;
    }

    ob::StateSamplerPtr PhysicsStateSpace::allocDefaultStateSampler() const
    {
        return std::make_shared<PhysicsStateSampler>(this);
    }
}  // namespace ompl_phys
