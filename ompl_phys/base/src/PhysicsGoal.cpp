#include "ompl_phys/base/PhysicsGoal.h"

#include <ompl/base/SpaceInformation.h>

#include <cmath>
#include <limits>

namespace ompl_phys
{
    PhysicsGoal::PhysicsGoal(const ompl::base::SpaceInformationPtr &si,
                             std::shared_ptr<const ManipulationKnowledge> knowledge, BodyStates startStates)
        : ompl::base::GoalSampleableRegion(si),
          space_(*si->getStateSpace()->as<PhysicsStateSpace>()),
          knowledge_(std::move(knowledge)),
          start_(std::move(startStates)),
          centre_(space_.scene().goal.centre)
    {
        setThreshold(space_.scene().goal.radius);
    }

    double PhysicsGoal::distanceGoal(const ompl::base::State *state) const
    {
        return (space_.robotPosition(state) - centre_).norm();
    }

    void PhysicsGoal::sampleGoal(ompl::base::State *state) const
    {
        // uniform in the disc: radius by the square root of a uniform number
        const double radius = getThreshold() * std::sqrt(rng_.uniform01());
        const double angle = rng_.uniformReal(-M_PI, M_PI);
        const Eigen::Vector2d at = centre_ + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
        BodyStates states = start_;
        states[0].position.head<2>() = at;
        knowledge_->clearGoal(states, at, CLEARANCE);
        space_.writeState(states, state);
    }

    unsigned int PhysicsGoal::maxSampleCount() const
    {
        return std::numeric_limits<unsigned int>::max();
    }
}  // namespace ompl_phys
