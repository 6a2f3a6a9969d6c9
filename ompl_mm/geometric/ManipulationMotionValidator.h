#pragma once

#include "ompl_mm/collision/CollisionWorld.h"
#include "ompl_mm/primitives/Primitive.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/SpaceInformation.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <unordered_set>
#include <vector>

namespace ompl_mm
{
    /** OMPL's motion check for manipulation: a motion between two states is valid only when one of
        the primitives explains it (Primitive::explain: nothing moves but the robot; or an object is
        pushed with the tool at its standoff behind it; later primitives: carried in the grasp), its
        end state is valid and every configuration along it is collision-free, checked continuously
        (CollisionWorld::checkSweep), not at sampled states. OMPL's own DiscreteMotionValidator
        checks only sampled states, so it accepts objects that slide across the room while the robot
        is elsewhere, and parts of a motion it accepted may graze what its samples missed: OMPL's
        B-spline smoothing then leaves unchecked colliding states in a path. Here any part of a valid
        motion is valid. ManipulationSetup installs one; with it PathGeometric::check(), PathSimplifier,
        SimpleSetup::simplifySolution() and Benchmark's "correct solution" all judge manipulation
        paths correctly. It also names a segment's primitive (explain()), which ManipulationPath
        uses to relabel states changed by OMPL's simplifier.

        A continuous check of a long motion near triangle meshes can take a tenth of a second or
        more, so checks can be stopped by a planner termination condition between two rounds of
        their conservative advancement: passed to checkSweep(), or, for code that calls OMPL's
        checkMotion(s1, s2) and cannot pass one (OMPL's planners and PathSimplifier), set for a
        while with a TerminationScope. A check stopped that way reports the motion as not free
        (nothing of it shown free): stopping never lets an unchecked motion pass.

        The validator remembers the last SWEEP_MEMORY motions whose continuous check it found free
        and that took long enough (setShortestRememberedSweep()), by their two states' values (a
        motion and its reverse pass through the same configurations: one is remembered for both),
        and checkMotion does not sweep such a motion again (it still asks the primitives and checks
        the probes and the end state): a path's re-check after planning (PathGeometric::check())
        meets, bit for bit, motions that MOPL's walks (the goal tree's in reverse) and the
        smoothing checked, and with triangle meshes each sweep costs milliseconds. The collision
        world is fixed, so a remembered sweep proves what a new one would. */
    class ManipulationMotionValidator : public ompl::base::MotionValidator
    {
    public:
        /** A validator for si, whose state space must be a ManipulationStateSpace; the primitives
            are the motions it accepts. @pre si outlives the validator (as for OMPL's validators). */
        ManipulationMotionValidator(const ompl::base::SpaceInformationPtr &si,
                                    std::vector<PrimitivePtr> primitives);
        ~ManipulationMotionValidator() override;
        ManipulationMotionValidator(const ManipulationMotionValidator &) = delete;  ///< owns a state
        ManipulationMotionValidator &operator=(const ManipulationMotionValidator &) =
            delete;  ///< owns a state

        /** The primitives it asks. */
        const std::vector<PrimitivePtr> &primitives() const { return primitives_; }

        /** The label of the first primitive that explains the motion from s1 to s2 (collisions
            aside), or nothing. */
        std::optional<SegmentLabel> explain(const ompl::base::State *s1, const ompl::base::State *s2) const;

        /** OMPL's hook: true when a primitive explains the motion, s2 is valid and every
            configuration from s1 to s2 is collision-free. Before the continuous check it tries
            the states at PROBES evenly spaced fractions of the way: most motions that fail do so
            there, for a fraction of a sweep's cost (and a state of a valid motion is valid, so the
            probes reject nothing the sweep would accept). @pre s1 is valid (as for OMPL's
            validators). */
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        /** States checkMotion(s1, s2) tries before the continuous check. */
        static constexpr unsigned int PROBES = 3;
        /** Motions found free whose sweeps the validator remembers (see the class), the oldest
            forgotten first. */
        static constexpr std::size_t SWEEP_MEMORY = 1024;
        /** Sweeps found free are remembered when they took at least this long, seconds (0: all);
            20 microseconds by default: remembering one costs about a microsecond, and quicker
            sweeps (those of convex shapes) are cheaper to repeat. */
        void setShortestRememberedSweep(double seconds) { shortestRemembered_ = seconds; }
        /** How long a free sweep must take to be remembered, seconds. */
        double getShortestRememberedSweep() const { return shortestRemembered_; }
        /** OMPL's hook: as above; when invalid, lastValid holds a valid state along the motion
            that keeps CollisionWorld::SAFE_CLEARANCE (s1 when no primitive explains the motion)
            and its fraction of the way. */
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

        /** The collision part of checkMotion alone, for motions a primitive made (MOPL's walks):
            whether every configuration from s1 to s2 is collision-free, and a safe fraction. */
        CollisionWorld::SweepCheck checkSweep(const ompl::base::State *s1, const ompl::base::State *s2) const;
        /** As checkSweep(s1, s2), but gives up, before it starts or between two of its rounds, once
            ptc is true: then the motion is reported as not free with a safe fraction of 0. */
        CollisionWorld::SweepCheck checkSweep(const ompl::base::State *s1, const ompl::base::State *s2,
                                              const ompl::base::PlannerTerminationCondition &ptc) const;

        /** While it lives, every check of a validator (checkMotion, checkSweep) also gives up once
            its termination condition is true, the motion then invalid (not free, safe fraction 0):
            for callers of checkMotion(s1, s2) that cannot pass a condition, such as OMPL's planners
            and PathSimplifier. Scopes nest; every live scope's condition counts. Make and end
            scopes of one validator in last-in, first-out order (as local variables); not copyable. */
        class TerminationScope
        {
        public:
            /** Makes validator's checks stop at ptc until this scope ends.
                @pre validator outlives the scope. */
            TerminationScope(ManipulationMotionValidator &validator,
                             const ompl::base::PlannerTerminationCondition &ptc);
            /** Ends the scope: the validator no longer stops at this condition. */
            ~TerminationScope();
            TerminationScope(const TerminationScope &) = delete;             ///< one scope, one end
            TerminationScope &operator=(const TerminationScope &) = delete;  ///< one scope, one end

        private:
            ManipulationMotionValidator &validator_;
        };

    private:
        /** Whether a primitive explains the motion, (with probe) the PROBES states along it are
            valid, every configuration along it is collision-free and s2 is valid, with the safe
            fraction of the continuous check (0 when it did not run or s2 is invalid); counted as a
            valid or invalid motion. */
        CollisionWorld::SweepCheck judge(const ompl::base::State *s1, const ompl::base::State *s2,
                                         bool probe) const;
        /** The continuous check, stopped (not free, safe fraction 0) once ptc (may be null) or a
            live TerminationScope's condition is true. */
        CollisionWorld::SweepCheck sweep(const ompl::base::State *s1, const ompl::base::State *s2,
                                         const ompl::base::PlannerTerminationCondition *ptc) const;
        /** True when ptc (may be null) or a live TerminationScope's condition is true. */
        bool stopped(const ompl::base::PlannerTerminationCondition *ptc) const;
        /** The continuous check: (with lookUp) free at once when the motion is remembered, else
            sweep(), remembered when free and not quick; not free when stopped. */
        CollisionWorld::SweepCheck rememberedSweep(const ompl::base::State *s1, const ompl::base::State *s2,
                                                   const ompl::base::PlannerTerminationCondition *ptc,
                                                   bool lookUp) const;

        /** Hashes the values of a motion's two states (FNV-1a over their bytes). */
        struct ValuesHash
        {
            std::size_t operator()(const std::vector<double> &values) const;
        };
        /** The same values bit for bit (so that 0 and -0 differ, as their hashes do). */
        struct SameBits
        {
            bool operator()(const std::vector<double> &a, const std::vector<double> &b) const;
        };

        /** A state seen as a collision configuration: its object poses and resting surfaces (the
    joints are read in place). */
        struct ConfigurationOf
        {
            std::vector<ObjectPose> poses;
            std::vector<int> resting;
            CollisionWorld::Configuration read(const ManipulationStateSpace &space,
                                               const ompl::base::State *state);
        };

        std::vector<PrimitivePtr> primitives_;
        const ManipulationStateSpace *space_;
        CollisionWorld world_;
        // buffers of checkSweep, kept to spare allocations in planners' inner loops
        mutable ConfigurationOf from_, to_, alongConfiguration_;
        ompl::base::State *along_;
        /** the conditions of the live TerminationScopes, innermost last */
        std::vector<ompl::base::PlannerTerminationCondition> scopedConditions_;
        /** the remembered free sweeps: both states' values, one after the other */
        mutable std::unordered_set<std::vector<double>, ValuesHash, SameBits> freeSweeps_;
        /** the remembered sweeps, oldest first (elements of freeSweeps_, whose nodes do not move) */
        mutable std::deque<const std::vector<double> *> freeSweepOrder_;
        mutable std::vector<double> motionValues_, stateValues_;  ///< scratch of rememberedSweep
        double shortestRemembered_{20e-6};  ///< seconds, see setShortestRememberedSweep()
    };
}  // namespace ompl_mm
