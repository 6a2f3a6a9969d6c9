#include "ompl_phys/base/PhysicsValidityChecker.h"

#include <ompl/base/SpaceInformation.h>

namespace ompl_phys
{
    PhysicsValidityChecker::PhysicsValidityChecker(const ompl::base::SpaceInformationPtr &si,
                                                   std::shared_ptr<const ManipulationKnowledge> knowledge)
        : ompl::base::StateValidityChecker(si),
          space_(*si->getStateSpace()->as<PhysicsStateSpace>()),
          knowledge_(std::move(knowledge))
    {
    }

    bool PhysicsValidityChecker::isValid(const ompl::base::State *state) const
    {
        return violation(state) == Violation::None;
    }

    Violation PhysicsValidityChecker::violation(const ompl::base::State *state) const
    {
        const Violation simulated = state->as<PhysicsStateSpace::StateType>()->violation;
        if (simulated != Violation::None)
            return simulated;
        thread_local BodyStates states;
        space_.readState(state, states);
        return knowledge_->checkStates(states);
    }
}  // namespace ompl_phys
