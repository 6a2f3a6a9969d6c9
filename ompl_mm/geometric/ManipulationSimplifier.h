#pragma once

#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/geometric/PathRouter.h"
#include "ompl_mm/geometric/PushReversalRemover.h"
#include "ompl_mm/geometric/ToolPathStraightener.h"
#include "ompl_mm/primitives/EmptySpacePlanner.h"

#include <ompl/base/Goal.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <optional>

namespace ompl_mm
{
    /** Mode-aware smoothing of manipulation paths, the one MOPL applies to its solutions (OMPL's
        PathSimplifier only straightens motions one at a time and cannot drop a manipulation):
        1. carries once what was carried twice in a row (carryOnce()), then pushes what only
           slides: an object picked up and put down again on the level it stood
           on is pushed there instead when the push primitives can, the robot routed to the push
           and on to where the carry's transits led, and the tool travels less (pushCarries());
           then removes pointless manipulation: an object pushed away and later back to where it was is
           left where it was (the pushes become the robot's transits, routed around the object
           where they meet it) or, when that fails, the return push ends early (where it found the
           object, or at one of its waypoints short of the start) and the object stays there for
           the rest of the way, if the goal still holds; a push that moves an object back
           against the push of it before (ManipulationPath::pushReversals) is dropped or made
           shorter, the push run before ending where it comes nearest to where the object is
           wanted, or the object is pushed aside instead of back (PushReversalRemover); then every
           push run ends as early as it may (dropped, or ended at one of its waypoints, the object
           staying there for the rest of the way) when the goal still holds and the tool travels
           no farther;
        2. replans random windows of the path, from the start of one primitive run to the end of
           a later one, with the empty-space planner (the primitives chained straight from the
           window's first to its last state: one push instead of several of the same object, no
           detour between them, …) and keeps a window when every motion of it is valid and the
           tool travels less; on the planner's raw path, where such a chain is more often the
           shorter, and before OMPL's steps, which then straighten the chains too;
        3. runs the steps of OMPL's PathSimplifier (shortcuts, B-spline smoothing, vertex
           reduction), seeded from the caller's RNG, on a copy kept when all of it is valid and
           shorter; with the motion validator they shorten push runs as well as transit runs but
           never make an object move on its own (with simulated pushes, each stretch between push
           runs on its own);
        4. brings an arm's tool closer to straight lines along its transits and transfers
           (ToolPathStraightener), or, where the tool moves straight already, runs step 3 again.
        Every change is checked with the ManipulationMotionValidator, so the result is as valid as
        the input. A termination condition (a planner's time limit) stops it between these steps
        and within them (through a StepTermination view of it): between primitive applications
        and inverse kinematics attempts, RRT iterations, windows and bisection probes, and,
        through the validator (a TerminationScope for the whole run), within every motion check,
        OMPL's steps included; what is done by then is kept, so the path stays valid.
        Deterministic for a given RNG state, as long as it is not stopped. Not thread-safe (it
        reuses its empty-space planner's scratch space). */
    class ManipulationSimplifier
    {
    public:
        /** What simplify() did. */
        struct Outcome
        {
            unsigned int carriesMerged{0};      ///< two carries of an object in a row made one
            unsigned int carriesPushed{0};      ///< carries replaced by pushes
            unsigned int roundTripsRemoved{0};  ///< objects no longer pushed away and back
            unsigned int reversalsRemoved{0};   ///< pushes no longer moving an object back
            unsigned int pushesShortened{0};    ///< push runs ended early or dropped
            unsigned int windowsReplanned{0};   ///< windows replaced by shorter primitive chains
        };

        /** A simplifier for paths in si, with the primitives of its motion validator.
            @throws ompl::Exception when si's motion validator is no ManipulationMotionValidator. */
        explicit ManipulationSimplifier(const ompl::base::SpaceInformationPtr &si);

        /** Simplifies path in place with `windowAttempts` random windows, drawing from rng. goal
            (may be null: the path's end then stays where it is) tells whether a changed end
            still solves the problem. Stops soon after ptc becomes true (a planner's time limit),
            within a step (see the class), with the valid path simplified so far. */
        Outcome simplify(ManipulationPath &path, unsigned int windowAttempts, ompl::RNG &rng,
                         const ompl::base::Goal *goal,
                         const ompl::base::PlannerTerminationCondition &ptc =
                             ompl::base::plannerNonTerminatingCondition()) const;

        /** Whether some push's outcome is simulated (a primitive of the motion validator whose
            Primitive::endsWhereAsked() is false): where such a push leaves its object is physics'
            answer, which a shorter push would change, so the simplifier then neither shortens
            pushes nor removes round trips, and OMPL's steps run on the stretches between push runs
            only. */
        bool pushesSimulated() const { return pushesSimulated_; }

        /** Seconds the simplifier's own inverse kinematics took (ToolPathStraightener; the
            windows' primitives time theirs). */
        double inverseKinematicsTime() const { return straightener_.ikTime(); }

        /** Number of round trips in path: push runs (consecutive segments pushing one object)
            after which the object stands where it stood before the same or an earlier push run
            of it. */
        static unsigned int countRoundTrips(const ManipulationPath &path);

    private:
        /** Two carries of one object in a row (nothing else moving it between): states of the
            first carry's start, its end, the second's start and end. */
        struct CarryPair
        {
            unsigned int object;
            std::size_t first, firstLast, secondFirst, secondLast;
        };
        /** Makes one carry of each pair of carries of an object in a row that it can: the object
            carried from where the first carry picks it up straight to where the second puts it
            down, the robot then on its old way between them (the object standing there, routed
            around it) and on to where the transits after the second carry end; kept when every
            motion is valid and, both ways shortened by OMPL's shortcuts, the tool travels less;
            the last pair first. Returns how many pairs became one carry. */
        unsigned int carryOnce(ManipulationPath &path, ompl::RNG &rng,
                               const ompl::base::PlannerTerminationCondition &ptc) const;
        /** One pair of carries made one (see carryOnce(), a few carry plans and routes at most);
            true when the path changed. */
        bool carryOnceInstead(ManipulationPath &path, const CarryPair &pair, ompl::RNG &rng,
                              const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Chains states (PathRouter::routeThrough, CARRY_ROUTE_ITERATIONS; frees them) and,
            when that works and the result, shortened by OMPL's shortcuts, makes the tool travel
            less than path's states first … last shortened the same way (kept in before, made on
            the first call), puts the result in shorter. */
        void keepIfShorter(std::vector<ompl::base::State *> &states, const ManipulationPath &path,
                           std::size_t first, std::size_t last, std::optional<ManipulationPath> &before,
                           std::optional<ManipulationPath> &shorter, ompl::RNG &rng,
                           const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Puts replacement, when there is one, in place of path's states first … last; true when
            it did. */
        bool replaceWith(ManipulationPath &path, std::size_t first, std::size_t last,
                         const std::optional<ManipulationPath> &replacement) const;
        /** Replaces each carry (a run of pickup and transfer segments of one object, with the
            robot's transits before and after it) that the push primitives can do instead: the
            object pushed from where it stands to where the carry puts it down, the robot routed
            (TransitConnector) to the push and from its end to where the carry's transits end,
            kept when every motion is valid and, both ways shortened by OMPL's shortcuts, the
            tool travels less; the last carry first. Returns how many were replaced. */
        unsigned int pushCarries(ManipulationPath &path, ompl::RNG &rng,
                                 const ompl::base::PlannerTerminationCondition &ptc) const;
        /** The carry of `object` in states first … last replaced by pushes (see pushCarries(),
            a few push plans and routes at most); true when the path changed. */
        bool pushInsteadOfCarry(ManipulationPath &path, unsigned int object, std::size_t first,
                                std::size_t last, ompl::RNG &rng,
                                const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Removes one round trip if it can (trying until ptc is true); true when the path changed. */
        bool removeRoundTrip(ManipulationPath &path, const ompl::base::Goal *goal, ompl::RNG &rng,
                             const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Ends each push run at its earliest waypoint after which the object may stay where it
            is for the rest of the way (PathRouter::holdObject), the run's start first (no push at
            all), when the end still satisfies goal and the tool travels no farther; returns how
            many runs changed. */
        unsigned int shortenPushes(ManipulationPath &path, const ompl::base::Goal *goal, ompl::RNG &rng,
                                   const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Shortens path with one round of the steps of OMPL's PathSimplifier (see the class
            comment); leaves it as it is when ptc becomes true before the round's copy is checked. */
        void shortenWithOMPL(ManipulationPath &path, ompl::RNG &rng,
                             const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Step 3 on the whole path; with simulated pushes, which OMPL's steps cannot change, on
            each stretch between push runs alone: OMPL's vertex collapsing takes time cubic in the
            states, and a simulated push leaves a waypoint every few centimetres. */
        void shortenStretches(ManipulationPath &path, ompl::RNG &rng,
                              const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Replans states first … last with the empty-space planner (until ptc is true); true when
            the path changed. */
        bool replanWindow(ManipulationPath &path, std::size_t first, std::size_t last, ompl::RNG &rng,
                          const ompl::base::PlannerTerminationCondition &ptc) const;
        /** OMPL's shortcuts on path (a few passes, while they find some), until ptc is true. */
        void shortcut(ManipulationPath &path, ompl::RNG &rng,
                      const ompl::base::PlannerTerminationCondition &ptc) const;
        /** True when every segment of the trajectory is a valid motion. */
        bool isValid(const Trajectory &trajectory) const;

        ompl::base::SpaceInformationPtr si_;
        const ManipulationStateSpace *space_;
        /** the space information's validator (its TerminationScope bounds the motion checks) */
        std::shared_ptr<ManipulationMotionValidator> validator_;
        mutable EmptySpacePlanner planner_;
        /** the empty-space planner of the push primitives alone (those that end where asked) */
        mutable EmptySpacePlanner pushPlanner_;
        PathRouter router_;
        PushReversalRemover reversals_;
        mutable ToolPathStraightener straightener_;
        bool pushesSimulated_;  ///< see pushesSimulated()
    };
}  // namespace ompl_mm
