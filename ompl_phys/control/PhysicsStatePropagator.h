#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/control/SpeedGovernor.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"
#include "ompl_phys/world/PhysicsWorld.h"

#include <ompl/control/StatePropagator.h>

#include <array>

namespace ompl_phys
{
    /** Propagates a physics state under a control (a horizontal force on the robot, N, world x and
        y) by simulating the ODE world: write the state into the world, step it in `substeps` ODE
        steps per propagation step with the robot's drive applying the force (SpeedGovernor holds
        back what would break the speed limit), judge every sub-step by the manipulation knowledge
        and the planning limits, read the state back. A sub-step that breaks a rule ends the simulation
        there and marks the result with the violation, which the validity checker rejects, so
        propagateWhileValid stops at the last good step. ODE's random generator is reset on every
        call: the same state and control always give a bit-identical result.

        Not thread-safe: every call simulates in the one shared world and counts in counters(), so
        planners must not propagate from several threads at once.

        @par External documentation
        Muhayyuddin, A. Akbari, J. Rosell, "Physics-based Motion Planning: Evaluation Criteria and
        Benchmarking", ROBOT 2015: Second Iberian Robotics Conference, Advances in Intelligent
        Systems and Computing vol. 417, Springer, 2016, pp. 43–55, DOI 10.1007/978-3-319-27146-0_4. */
    class PhysicsStatePropagator : public ompl::control::StatePropagator
    {
    public:
        /** What the propagator has done since construction or resetCounters(). */
        struct Counters
        {
            unsigned long long propagations{0};                       ///< calls of propagate()
            unsigned long long substeps{0};                           ///< ODE steps taken
            std::array<unsigned long long, VIOLATION_KINDS> stops{};  ///< propagations ended, per Violation
        };

        /** Propagates states of si's space, which must be a PhysicsStateSpace; the step and the
            sub-steps per step come from the world's scene. Shares the world it simulates in and
            the knowledge it judges by, and keeps both alive. */
        PhysicsStatePropagator(const ompl::control::SpaceInformationPtr &si,
                               std::shared_ptr<PhysicsWorld> world,
                               std::shared_ptr<const ManipulationKnowledge> knowledge);

        /** OMPL's hook: simulates control (force, N) for duration seconds from state into result, in
            round(duration / step · substeps) equal ODE steps (at least one). A state that already
            carries a violation is copied unchanged: a broken state stays broken. */
        void propagate(const ompl::base::State *state, const ompl::control::Control *control, double duration,
                       ompl::base::State *result) const override;

        /** OMPL's hook: false, physics runs forward only. */
        bool canPropagateBackward() const override { return false; }

        /** The impulse the robot's drive applied in the last propagate() call (the sum of the
            applied force times the sub-step), N·s: the control's force times the duration unless
            the speed limit held the drive back (SpeedGovernor). */
        const Eigen::Vector2d &lastImpulse() const { return impulse_; }

        /** The counts since construction or resetCounters(). */
        const Counters &counters() const { return counters_; }
        /** Sets every count to 0. */
        void resetCounters() { counters_ = Counters(); }
        /** Sets the counts back to earlier ones, so that simulating for something other than
            planning (listing a tree, say) leaves them as planning left them. */
        void restoreCounters(const Counters &counters) const { counters_ = counters; }

    private:
        const PhysicsStateSpace &space_;
        std::shared_ptr<PhysicsWorld> world_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
        SpeedGovernor governor_;
        double stepSize_;
        unsigned int substepsPerStep_;
        mutable BodyStates states_;
        mutable Eigen::Vector2d impulse_{Eigen::Vector2d::Zero()};
        mutable Counters counters_;
    };
}  // namespace ompl_phys
