#pragma once

#include <memory>

#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"

#include <ompl/base/StateValidityChecker.h>

namespace ompl_phys
{
    /** A state of a physics scene is valid when simulating into it broke no rule (the violation the
        propagator stored in it) and it satisfies the knowledge's state rules and the planning
        limits. Contacts are judged during propagation, where they happen; see
        ManipulationKnowledge. Safe to call from several threads. */
    class PhysicsValidityChecker : public ompl::base::StateValidityChecker
    {
    public:
        /** Checks states of si's space, which must be a PhysicsStateSpace; shares the knowledge it
            judges by, which it keeps alive. */
        PhysicsValidityChecker(const ompl::base::SpaceInformationPtr &si,
                               std::shared_ptr<const ManipulationKnowledge> knowledge);

        /** OMPL's hook: whether violation() finds nothing. */
        bool isValid(const ompl::base::State *state) const override;

        /** The violation that makes state invalid, or Violation::None: the one stored by the
            propagator, else the first the knowledge finds in the state. */
        Violation violation(const ompl::base::State *state) const;

    private:
        const PhysicsStateSpace &space_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
    };
}  // namespace ompl_phys
