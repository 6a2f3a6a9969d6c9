/* A state of a physics scene is valid when simulating into it broke no rule (the violation the
   propagator stored in it) and it satisfies the knowledge's state rules and the planning limits.
   Contacts are judged during propagation, where they happen; see ManipulationKnowledge. */
#pragma once

#include <memory>

#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"

#include <ompl/base/StateValidityChecker.h>

namespace ompl_phys
{
    class PhysicsValidityChecker : public ompl::base::StateValidityChecker
    {
    public:
        /** Shares the knowledge it judges by. */
        PhysicsValidityChecker(const ompl::base::SpaceInformationPtr &si,
                               std::shared_ptr<const ManipulationKnowledge> knowledge);

        bool isValid(const ompl::base::State *state) const override;

        /** The violation that makes state invalid, or Violation::None. */
        Violation violation(const ompl::base::State *state) const;

    private:
        const PhysicsStateSpace &space_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
    };
}  // namespace ompl_phys
