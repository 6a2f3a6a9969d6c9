/* Propagates a physics state under a control (a horizontal force on the robot, N) by simulating
   the ODE world: write the state into the world, step it in `substeps` ODE steps per propagation
   step, judge every sub-step by the manipulation knowledge and the planning limits, read the
   state back. A sub-step that breaks a rule ends the simulation there and marks the result with
   the violation, which the validity checker rejects, so propagateWhileValid stops at the last
   good step. ODE's random generator is reset on every call: the same state and control always
   give a bit-identical result. */
#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"
#include "ompl_phys/world/PhysicsWorld.h"

#include <ompl/control/StatePropagator.h>

#include <array>

namespace ompl_phys
{
    class PhysicsStatePropagator : public ompl::control::StatePropagator
    {
    public:
        /** What the propagator has done since construction or resetCounters(). */
        struct Counters
        {
            unsigned long long propagations{0};                       ///< calls of propagate()
            unsigned long long substeps{0};                           ///< ODE steps taken
            std::array<unsigned long long, VIOLATION_KINDS> stops{};  ///< propagations ended, by violation
        };

        /** Shares the world it simulates in and the knowledge it judges by. */
        PhysicsStatePropagator(const ompl::control::SpaceInformationPtr &si,
                               std::shared_ptr<PhysicsWorld> world,
                               std::shared_ptr<const ManipulationKnowledge> knowledge);

        void propagate(const ompl::base::State *state, const ompl::control::Control *control, double duration,
                       ompl::base::State *result) const override;

        bool canPropagateBackward() const override { return false; }

        const Counters &counters() const { return counters_; }
        void resetCounters() { counters_ = Counters(); }

    private:
        const PhysicsStateSpace &space_;
        std::shared_ptr<PhysicsWorld> world_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
        double stepSize_;
        unsigned int substepsPerStep_;
        mutable BodyStates states_;
        mutable Counters counters_;
    };
}  // namespace ompl_phys
