#pragma once

#include "ompl_mm/primitives/Primitive.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include <optional>
#include <vector>

namespace ompl_mm
{
    /** OMPL's motion check for manipulation: a motion between two states is valid only when one of
        the primitives explains it (Primitive::explain: nothing moves but the robot; or an object is
        pushed with the tool at its standoff behind it; later primitives: carried in the grasp) and
        every state along it is valid at the space's collision resolution. OMPL's own DiscreteMotionValidator
        checks only the states, so it accepts objects that slide across the room while the robot is
        elsewhere. ManipulationSetup installs one; with it PathGeometric::check(), PathSimplifier,
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

        /** The primitives it asks. */
        const std::vector<PrimitivePtr> &primitives() const { return primitives_; }

        /** The label of the first primitive that explains the motion from s1 to s2 (collisions
            aside), or nothing. */
        std::optional<SegmentLabel> explain(const ompl::base::State *s1, const ompl::base::State *s2) const;

        /** OMPL's hook: true when a primitive explains the motion and every state along it
            (including s2, not s1) is valid; the states are checked in halving order, as OMPL's
            DiscreteMotionValidator does, so that collisions show early. */
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        /** OMPL's hook: as above; when invalid, lastValid holds the last valid state along the
            motion (s1 when no primitive explains it) and its fraction of the way. */
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

    private:
        /** The number of check steps of a motion (at least 1) and how many of them, from the
            first, reach a valid state. */
        struct StepCheck
        {
            unsigned int steps;
            unsigned int valid;
        };
        /** Checks the states at 1/n, 2/n, … 1 of the motion in order, stopping at the first
            invalid one. */
        StepCheck checkSteps(const ompl::base::State *s1, const ompl::base::State *s2) const;

        std::vector<PrimitivePtr> primitives_;
    };
}  // namespace ompl_mm
