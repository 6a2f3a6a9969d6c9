#pragma once

#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/robot/IkSolver.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

namespace ompl_mm
{
    /** Brings an arm's tool closer to straight lines between the waypoints of its transits and
        transfers. A motion straight in joint space moves the tool of an arm along an arc, often a
        third longer than the chord on KUKA TABLE's plans; shortcuts and B-splines work in joint
        space and keep the arcs. For each such motion whose tool arc exceeds its chord by more than
        MIN_EXCESS, this adds a waypoint: the joint-space midpoint's tool moved onto the chord's
        midpoint (turned as it is there), found by 6-D inverse kinematics from that midpoint alone
        (IkScope::NearSeed, so the arm keeps its shape), a carried object kept in its grasp. It is
        kept when the tool travels less and both new motions are valid; while they collide, the
        same is tried raised (RAISES). Then again on the halves, LEVELS deep. Robots whose motions
        move the tool straight already (mobile bases) are left as they are, at the cost of one
        tool-travel measure per motion. Deterministic; not thread-safe (its solver has work
        space). */
    class ToolPathStraightener
    {
    public:
        /** For paths in si, whose motion validator must be a ManipulationMotionValidator.
            @throws ompl::Exception otherwise. */
        explicit ToolPathStraightener(const ompl::base::SpaceInformationPtr &si);

        /** Straightens path in place; stops early, the path valid, when ptc says so (between
            motions; a motion check under way stops only through the validator: see
            ManipulationMotionValidator::TerminationScope). Returns the waypoints added. */
        unsigned int straighten(ManipulationPath &path, const ompl::base::PlannerTerminationCondition &ptc);

        /** Seconds spent in inverse kinematics since construction. */
        double ikTime() const { return ik_.time(); }

        /** How much longer than its chord a transit's tool path must be to be worth a waypoint,
            metres. */
        static constexpr double MIN_EXCESS = 0.01;
        /** Halvings of a motion at most. */
        static constexpr unsigned int LEVELS = 4;
        /** Heights above the chord's midpoint tried for the new waypoint, metres, in turn while
            its motions collide: over what lies on the chord (a table's edge). */
        static constexpr double RAISES[] = {0.0, 0.1, 0.2};

    private:
        /** The waypoint halfway along the tool chord between a and b, into mid; false when none
            is found or it does not shorten the tool's travel. */
        bool halfway(const ompl::base::State *a, const ompl::base::State *b, const SegmentLabel &label,
                     ompl::base::State *mid);

        ompl::base::SpaceInformationPtr si_;
        const ManipulationStateSpace *space_;
        IkSolver ik_;
        ompl::RNG rng_{1};  ///< what the solver asks for; NearSeed solves draw nothing from it
    };
}  // namespace ompl_mm
