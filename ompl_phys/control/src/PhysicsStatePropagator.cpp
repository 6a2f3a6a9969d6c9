#include "ompl_phys/control/PhysicsStatePropagator.h"

#include <cassert>

#include <ompl/control/SpaceInformation.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <algorithm>
#include <cmath>

namespace ompl_phys
{
    PhysicsStatePropagator::PhysicsStatePropagator(const ompl::control::SpaceInformationPtr &si,
                                                   std::shared_ptr<PhysicsWorld> world,
                                                   std::shared_ptr<const ManipulationKnowledge> knowledge)
        : ompl::control::StatePropagator(si),
          space_(*si->getStateSpace()->as<PhysicsStateSpace>()),
          world_(std::move(world)),
          knowledge_(std::move(knowledge)),
          governor_(world_->scene()),
          stepSize_(world_->scene().limits.stepSize),
          substepsPerStep_(world_->scene().contact.substeps)
    {
    }

    void PhysicsStatePropagator::propagate(const ompl::base::State *state,
                                           const ompl::control::Control *control, double duration,
                                           ompl::base::State *result) const
    {
        ++counters_.propagations;
        impulse_.setZero();
        if (state->as<PhysicsStateSpace::StateType>()->violation != Violation::None)
        {
            space_.copyState(result, state);  // a broken state stays broken
            return;
        }
        const double *values = control->as<ompl::control::RealVectorControlSpace::ControlType>()->values;
        const Eigen::Vector2d commanded(values[0], values[1]);
        const auto substeps = static_cast<unsigned int>(
            std::max(1.0, std::round(duration / stepSize_ * static_cast<double>(substepsPerStep_))));
        const double dt = duration / substeps;

        PhysicsWorld::resetRandomSeed();
        space_.readState(state, states_);
        assert(states_.size() == world_->movingBodyCount());  // the space and the world hold the same bodies
        world_->setStates(states_);
        Violation violation = Violation::None;
        for (unsigned int k = 0; k < substeps && violation == Violation::None; ++k)
        {
            const Eigen::Vector2d applied =
                governor_.force(commanded, states_[0].linearVelocity.head<2>(), dt);
            world_->step(applied, dt);
            impulse_ += applied * dt;
            ++counters_.substeps;
            // the robot's touches were found before the step: judge them at the poses of that moment
            violation = knowledge_->checkTouches(world_->touches(), states_);
            if (violation == Violation::None)
                violation = ManipulationKnowledge::checkPenetration(world_->deepestPenetration());
            world_->readStates(states_);
            if (violation == Violation::None)
                violation = knowledge_->checkStates(states_);
        }
        space_.writeState(states_, result);
        result->as<PhysicsStateSpace::StateType>()->violation = violation;
        if (violation != Violation::None)
            ++counters_.stops[static_cast<std::size_t>(violation)];
    }
}  // namespace ompl_phys
