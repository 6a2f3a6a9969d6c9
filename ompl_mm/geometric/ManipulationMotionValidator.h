#pragma once

#include "ompl_mm/collision/CollisionWorld.h"
#include "ompl_mm/primitives/Primitive.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include <optional>
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
        uses to relabel states changed by OMPL's simplifier. */
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
        /** OMPL's hook: as above; when invalid, lastValid holds a valid state along the motion
            that keeps CollisionWorld::SAFE_CLEARANCE (s1 when no primitive explains the motion)
            and its fraction of the way. */
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

        /** The collision part of checkMotion alone, for motions a primitive made (MOPL's walks):
            whether every configuration from s1 to s2 is collision-free, and a safe fraction. */
        CollisionWorld::SweepCheck checkSweep(const ompl::base::State *s1, const ompl::base::State *s2) const;

    private:
        /** Whether a primitive explains the motion, (with probe) the PROBES states along it are
            valid, every configuration along it is collision-free and s2 is valid, with the safe
            fraction of the continuous check (0 when it did not run or s2 is invalid); counted as a
            valid or invalid motion. */
        CollisionWorld::SweepCheck judge(const ompl::base::State *s1, const ompl::base::State *s2,
                                         bool probe) const;

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
    };
}  // namespace ompl_mm
