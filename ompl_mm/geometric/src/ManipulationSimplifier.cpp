#include "ompl_mm/geometric/ManipulationSimplifier.h"

#include "ompl_core/compat/OmplVersions.h"
#include "ompl_mm/base/StepTermination.h"
#include "ompl_mm/geometric/CloseStateCollapse.h"

#include <ompl/geometric/PathSimplifier.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <optional>

namespace ompl_mm
{
    namespace
    {
        constexpr double SAME_POSE = 1e-6;
        // calls of OMPL's shortcutPath in a round, each trying as many shortcuts as the path has states
        constexpr unsigned int SHORTCUT_PASSES = 5;
        // RRT iterations to route the robot around an object it no longer pushes after a push
        // that ends early (fewer than PathRouter's: each push run tries several waypoints)
        constexpr unsigned int SHORTER_PUSH_CONNECT_ITERATIONS = 50;
        // empty-space plans of pushes tried in place of a carry (each push primitive's inverse
        // kinematics draws new solutions each time)
        constexpr unsigned int CARRY_PUSH_TRIES = 5;
        // empty-space plans of one carry in place of two: fewer than of pushes, each costs routes in
        // the arm's joints (MEKA CLEAN-UP, 2 instead of 5: the smoothing's median 0.47 -> 0.28 s,
        // the tool path 0.4 % longer)
        constexpr unsigned int CARRY_ONCE_TRIES = 2;
        // RRT iterations of each route to and from such a push: more than after a round trip, as
        // the push starts and ends with the hand beside the object
        constexpr unsigned int CARRY_ROUTE_ITERATIONS = 5000;

        /** The runs of consecutive segments of `object` whose kind is one of kinds: first and last
            state of each. */
        std::vector<std::pair<std::size_t, std::size_t>> runsOf(const ManipulationPath &path,
                                                                unsigned int object,
                                                                std::initializer_list<PrimitiveKind> kinds)
        {
            std::vector<std::pair<std::size_t, std::size_t>> runs;
            const std::vector<SegmentLabel> &labels = path.labels();
            for (std::size_t i = 0; i < labels.size(); ++i)
            {
                if (std::find(kinds.begin(), kinds.end(), labels[i].kind) == kinds.end() ||
                    labels[i].object != static_cast<int>(object))
                    continue;
                if (!runs.empty() && runs.back().second == i)
                    runs.back().second = i + 1;
                else
                    runs.emplace_back(i, i + 1);
            }
            return runs;
        }

        /** The runs of consecutive segments that push `object`: first and last state of each. */
        std::vector<std::pair<std::size_t, std::size_t>> pushRuns(const ManipulationPath &path,
                                                                  unsigned int object)
        {
            return runsOf(path, object, {PrimitiveKind::Push});
        }

        /** True when something moves `object` between path's states from and to. */
        bool movesBetween(const ManipulationPath &path, unsigned int object, std::size_t from, std::size_t to)
        {
            const auto *space = path.getSpaceInformation()->getStateSpace()->as<ManipulationStateSpace>();
            for (std::size_t k = from; k < to; ++k)
                if (space->objectMoves(path.getState(k), path.getState(k + 1), object))
                    return true;
            return false;
        }

        bool samePose(const ObjectPose &a, const ObjectPose &b)
        {
            return (a.position - b.position).norm() < SAME_POSE && std::abs(a.yaw - b.yaw) < SAME_POSE;
        }

        /** OMPL's path simplifier drawing from a seed of ours, so that a simplification repeats
            per seed (its own RNG is seeded from OMPL's global seed sequence). */
        class SeededPathSimplifier : public ompl::geometric::PathSimplifier
        {
        public:
            SeededPathSimplifier(const ompl::base::SpaceInformationPtr &si, std::uint_fast32_t seed)
                : ompl::geometric::PathSimplifier(si)
            {
                rng_.setLocalSeed(seed);
            }
        };

        /** A copy of path's states first … last. */
        ManipulationPath subPath(const ManipulationPath &path, std::size_t first, std::size_t last)
        {
            ManipulationPath part(path.getSpaceInformation());
            part.appendFirst(path.getState(first));
            for (std::size_t k = first + 1; k <= last; ++k)
                part.appendLabelled(path.getState(k), path.label(k - 1));
            return part;
        }

        /** The trajectory of path's states and labels (for ManipulationPath::replace). */
        Trajectory asTrajectory(const ManipulationPath &path, const ManipulationStateSpace *space)
        {
            Trajectory trajectory(space);
            trajectory.reset(path.getState(0));
            for (std::size_t k = 1; k < path.getStateCount(); ++k)
                trajectory.append(path.getState(k), path.label(k - 1));
            return trajectory;
        }

        /** The path of trajectory's waypoints and labels. */
        ManipulationPath asPath(const Trajectory &trajectory, const ompl::base::SpaceInformationPtr &si)
        {
            ManipulationPath path(si);
            path.appendFirst(trajectory.state(0));
            for (std::size_t k = 1; k < trajectory.size(); ++k)
                path.appendLabelled(trajectory.state(k), trajectory.label(k - 1));
            return path;
        }

        /** The primitives that push and end where asked. */
        std::vector<PrimitivePtr> exactPushes(const std::vector<PrimitivePtr> &primitives)
        {
            std::vector<PrimitivePtr> pushes;
            std::copy_if(primitives.begin(), primitives.end(), std::back_inserter(pushes),
                         [](const PrimitivePtr &p)
                         { return p->kind() == PrimitiveKind::Push && p->endsWhereAsked(); });
            return pushes;
        }

        /** OMPL's shortcuts on path while they find some; their motion checks stop at ptc (the
            caller's TerminationScope), so one under way when it becomes true ends soon after. */
        void shortcutPasses(ompl::geometric::PathSimplifier &simplifier, ManipulationPath &path,
                            const ompl::base::PlannerTerminationCondition &ptc)
        {
            for (unsigned int k = 0; k < SHORTCUT_PASSES && !ptc; ++k)
                if (!ompl_core::partialShortcut(simplifier, path))
                    break;
        }

        /** The path's first and last state and every state where the label changes. */
        std::vector<std::size_t> runBoundaries(const ManipulationPath &path)
        {
            const std::vector<SegmentLabel> &labels = path.labels();
            std::vector<std::size_t> bounds{0};
            for (std::size_t i = 1; i < labels.size(); ++i)
                if (labels[i] != labels[i - 1])
                    bounds.push_back(i);
            bounds.push_back(labels.size());
            return bounds;
        }

        double toolTravel(const Trajectory &trajectory)
        {
            double length = 0.0;
            for (std::size_t k = 0; k + 1 < trajectory.size(); ++k)
                length += trajectory.space()->toolTravel(trajectory.state(k), trajectory.state(k + 1));
            return length;
        }
    }  // namespace

    ManipulationSimplifier::ManipulationSimplifier(const ompl::base::SpaceInformationPtr &si)
        : si_(si),
          space_(si->getStateSpace()->as<ManipulationStateSpace>()),
          validator_(std::dynamic_pointer_cast<ManipulationMotionValidator>(si->getMotionValidator())),
          planner_(space_, validator_ ? validator_->primitives() : std::vector<PrimitivePtr>()),
          pushPlanner_(space_,
                       exactPushes(validator_ ? validator_->primitives() : std::vector<PrimitivePtr>())),
          router_(si, validator_),
          reversals_(si, validator_),
          straightener_(si)
    {
        if (!validator_)
            throw ompl::Exception(
                "ManipulationSimplifier needs a ManipulationMotionValidator on the space "
                "information (ManipulationSetup installs one)");
        const std::vector<PrimitivePtr> &primitives = validator_->primitives();
        pushesSimulated_ = std::any_of(primitives.begin(), primitives.end(),
                                       [](const PrimitivePtr &p) { return !p->endsWhereAsked(); });
    }

    ManipulationSimplifier::Outcome ManipulationSimplifier::simplify(
        ManipulationPath &path, unsigned int windowAttempts, ompl::RNG &rng, const ompl::base::Goal *goal,
        const ompl::base::PlannerTerminationCondition &ptc) const
    {
        Outcome outcome;
        // ptc between the steps, as before; within them a view of it that asks again only when a
        // step takes long (a condition may count its evaluations). Every motion check of this
        // run, OMPL's steps' included, stops at it too (the motion then counts as invalid, so no
        // change rests on it)
        const StepTermination inner(ptc);
        const ompl::base::PlannerTerminationCondition &stop = inner.condition();
        const ManipulationMotionValidator::TerminationScope bounded(*validator_, stop);
        path.removeRepeatedStates();
        outcome.carriesMerged = carryOnce(path, rng, stop);
        if (!pushesSimulated_)
        {
            outcome.carriesPushed = pushCarries(path, rng, stop);
            while (!ptc && removeRoundTrip(path, goal, rng, stop))
                ++outcome.roundTripsRemoved;
            outcome.reversalsRemoved = reversals_.remove(path, goal, rng, stop);
            outcome.pushesShortened = shortenPushes(path, goal, rng, stop);
        }
        // windows from one primitive run's start to a later run's end: what OMPL's shortcuts cannot
        // do, since they keep every manipulation, is to chain primitives anew across runs
        for (unsigned int attempt = 0; attempt < windowAttempts && !ptc; ++attempt)
        {
            const std::vector<std::size_t> bounds = runBoundaries(path);
            if (bounds.size() < 3)
                break;
            const int n = static_cast<int>(bounds.size());
            const int first = rng.uniformInt(0, n - 3);
            const int last = rng.uniformInt(first + 2, n - 1);
            if (replanWindow(path, bounds[first], bounds[last], rng, stop))
                ++outcome.windowsReplanned;
        }
        if (!ptc)
            shortenStretches(path, rng, stop);
        // a second round of OMPL's steps only where the tool moves straight already (mobile
        // bases: 100 seeds of MOBILE BLOCKED 15.71 -> 15.29 m): on an arm its B-spline leaves many
        // short joint-space arcs that the straightener no longer takes on (KUKA TABLE, 100 seeds:
        // 7.89 m with it before the straightener, 7.61 m without)
        if (!ptc && straightener_.straighten(path, ptc) == 0 && !ptc)
            shortenStretches(path, rng, stop);
        path.removeRepeatedStates();
        return outcome;
    }

    unsigned int ManipulationSimplifier::countRoundTrips(const ManipulationPath &path)
    {
        const auto *space = path.getSpaceInformation()->getStateSpace()->as<ManipulationStateSpace>();
        unsigned int count = 0;
        for (unsigned int object = 0; object < space->objectCount(); ++object)
        {
            const auto runs = pushRuns(path, object);
            for (std::size_t j = 0; j < runs.size(); ++j)
                for (std::size_t i = 0; i <= j; ++i)
                    if (samePose(space->objectPose(path.getState(runs[i].first), object),
                                 space->objectPose(path.getState(runs[j].second), object)))
                    {
                        ++count;
                        break;
                    }
        }
        return count;
    }

    unsigned int ManipulationSimplifier::pushCarries(ManipulationPath &path, ompl::RNG &rng,
                                                     const ompl::base::PlannerTerminationCondition &ptc) const
    {
        if (pushPlanner_.primitives().empty())
            return 0;
        // the last carry first: a change replaces states from its start on, so the carries before
        // it keep their indices
        struct Carry
        {
            std::size_t first, last;
            unsigned int object;
        };
        std::vector<Carry> carries;
        for (unsigned int object = 0; object < space_->objectCount(); ++object)
            for (const auto &[first, last] :
                 runsOf(path, object, {PrimitiveKind::Pickup, PrimitiveKind::Transfer}))
                carries.push_back({first, last, object});
        std::sort(carries.begin(), carries.end(),
                  [](const Carry &a, const Carry &b) { return a.first > b.first; });
        unsigned int replaced = 0;
        for (Carry carry : carries)
        {
            // with the robot's transits before and after it, which the push's routes replace
            const std::vector<SegmentLabel> &labels = path.labels();
            while (carry.first > 0 && labels[carry.first - 1].kind == PrimitiveKind::Transit)
                --carry.first;
            while (carry.last < labels.size() && labels[carry.last].kind == PrimitiveKind::Transit)
                ++carry.last;
            if (!ptc && pushInsteadOfCarry(path, carry.object, carry.first, carry.last, rng, ptc))
                ++replaced;
        }
        return replaced;
    }

    bool ManipulationSimplifier::pushInsteadOfCarry(ManipulationPath &path, unsigned int object,
                                                    std::size_t first, std::size_t last, ompl::RNG &rng,
                                                    const ompl::base::PlannerTerminationCondition &ptc) const
    {
        // from where the carry begins, the object pushed to where it puts it down (the robot
        // ending anywhere); a carry that no push can do is no slide
        const std::vector<PrimitivePtr> &pushes = pushPlanner_.primitives();
        ompl::base::State *target = si_->cloneState(path.getState(first));
        space_->setObjectPose(target, object, space_->objectPose(path.getState(last), object));
        const bool slides =
            std::any_of(pushes.begin(), pushes.end(),
                        [&](const PrimitivePtr &p) { return p->isUseful(path.getState(first), target); });
        // each try draws new push solutions and a new route, until one is shorter; the two ways
        // compared after OMPL's shortcuts, which the later steps apply too (a route's detours
        // shrink more than the planner's transits do)
        Trajectory push(space_);
        std::optional<ManipulationPath> carried;
        std::optional<ManipulationPath> pushed;
        for (unsigned int attempt = 0; slides && attempt < CARRY_PUSH_TRIES && !pushed && !ptc; ++attempt)
        {
            if (pushPlanner_.plan(path.getState(first), target, push, rng, ptc, true) ==
                    EmptySpacePlanner::Outcome::Failed ||
                space_->anyObjectMoves(push.back(), target))
                continue;
            // then the robot on to where the carry ends, routed where the straight motions collide
            std::vector<ompl::base::State *> states;
            router_.appendCopies(push, 0, states);
            states.push_back(si_->cloneState(path.getState(last)));
            keepIfShorter(states, path, first, last, carried, pushed, rng, ptc);
        }
        si_->freeState(target);
        return replaceWith(path, first, last, pushed);
    }

    void ManipulationSimplifier::keepIfShorter(std::vector<ompl::base::State *> &states,
                                               const ManipulationPath &path, std::size_t first,
                                               std::size_t last, std::optional<ManipulationPath> &before,
                                               std::optional<ManipulationPath> &shorter, ompl::RNG &rng,
                                               const ompl::base::PlannerTerminationCondition &ptc) const
    {
        Trajectory routed(space_);
        const bool found = router_.routeThrough(states, routed, CARRY_ROUTE_ITERATIONS, rng, ptc);
        router_.freeAll(states);
        if (!found)
            return;
        if (!before)
        {
            before.emplace(subPath(path, first, last));
            shortcut(*before, rng, ptc);
        }
        ManipulationPath candidate = asPath(routed, si_);
        shortcut(candidate, rng, ptc);
        if (candidate.toolPathLength() < before->toolPathLength())
            shorter.emplace(std::move(candidate));
    }

    bool ManipulationSimplifier::replaceWith(ManipulationPath &path, std::size_t first, std::size_t last,
                                             const std::optional<ManipulationPath> &replacement) const
    {
        if (replacement)
            path.replace(first, last, asTrajectory(*replacement, space_));
        return replacement.has_value();
    }

    unsigned int ManipulationSimplifier::carryOnce(ManipulationPath &path, ompl::RNG &rng,
                                                   const ompl::base::PlannerTerminationCondition &ptc) const
    {
        // the last pair first: a change replaces states from its first carry's start on, so the
        // pairs before it keep their indices
        unsigned int merged = 0;
        std::size_t before = path.getStateCount();
        while (!ptc)
        {
            std::optional<CarryPair> last;
            for (unsigned int object = 0; object < space_->objectCount(); ++object)
            {
                const auto carries = runsOf(path, object, {PrimitiveKind::Pickup, PrimitiveKind::Transfer});
                for (std::size_t i = 0; i + 1 < carries.size(); ++i)
                    if (carries[i].first < before && (!last || carries[i].first > last->first) &&
                        !movesBetween(path, object, carries[i].second, carries[i + 1].first))
                        last = CarryPair{object, carries[i].first, carries[i].second, carries[i + 1].first,
                                         carries[i + 1].second};
            }
            if (!last)
                break;
            if (carryOnceInstead(path, *last, rng, ptc))
                ++merged;
            before = last->first;
        }
        return merged;
    }

    bool ManipulationSimplifier::carryOnceInstead(ManipulationPath &path, const CarryPair &pair,
                                                  ompl::RNG &rng,
                                                  const ompl::base::PlannerTerminationCondition &ptc) const
    {
        // with the robot's transits before the first carry and after the second, which the new
        // carry's routes replace
        const std::vector<SegmentLabel> &labels = path.labels();
        std::size_t first = pair.first;
        while (first > 0 && labels[first - 1].kind == PrimitiveKind::Transit)
            --first;
        std::size_t last = pair.secondLast;
        while (last < labels.size() && labels[last].kind == PrimitiveKind::Transit)
            ++last;
        // from where the first carry begins, the object carried to where the second puts it down
        const ObjectPose put = space_->objectPose(path.getState(pair.secondLast), pair.object);
        ompl::base::State *target = si_->cloneState(path.getState(first));
        space_->setObjectPose(target, pair.object, put);
        Trajectory carry(space_);
        std::optional<ManipulationPath> twice;
        std::optional<ManipulationPath> once;
        for (unsigned int attempt = 0; attempt < CARRY_ONCE_TRIES && !once && !ptc; ++attempt)
        {
            planner_.plan(path.getState(first), target, carry, rng, ptc, true);
            // up to where it puts the object down
            std::size_t down = 0;
            while (down < carry.size() && space_->objectMoves(carry.state(down), target, pair.object))
                ++down;
            if (down == carry.size() || space_->anyObjectMoves(carry.state(down), target))
                continue;
            // then the robot's old way between the carries, the object standing where the second
            // put it, and on to where the transits after the second carry end
            std::vector<ompl::base::State *> states;
            for (std::size_t k = 0; k <= down; ++k)
                states.push_back(si_->cloneState(carry.state(k)));
            router_.appendHeld(path, pair.firstLast + 1, pair.secondFirst, pair.object, put, states);
            states.push_back(si_->cloneState(path.getState(last)));
            keepIfShorter(states, path, first, last, twice, once, rng, ptc);
        }
        si_->freeState(target);
        return replaceWith(path, first, last, once);
    }

    bool ManipulationSimplifier::removeRoundTrip(ManipulationPath &path, const ompl::base::Goal *goal,
                                                 ompl::RNG &rng,
                                                 const ompl::base::PlannerTerminationCondition &ptc) const
    {
        for (unsigned int object = 0; object < space_->objectCount(); ++object)
        {
            const auto runs = pushRuns(path, object);
            for (std::size_t i = 0; i < runs.size(); ++i)
                for (std::size_t j = runs.size(); j-- > i;)
                {
                    if (ptc)
                        return false;
                    const ObjectPose before = space_->objectPose(path.getState(runs[i].first), object);
                    if (!samePose(before, space_->objectPose(path.getState(runs[j].second), object)))
                        continue;
                    // leave the object where it was; or, when that fails, end the return early (where
                    // it found the object, or at one of its waypoints short of the start) and leave
                    // the object there for the rest of the way
                    if (router_.holdObject(path, object, before, runs[i].first, runs[j].second, goal,
                                           PathRouter::CONNECT_ITERATIONS, rng, ptc))
                        return true;
                    for (std::size_t stop = runs[j].first; stop < runs[j].second && !ptc; ++stop)
                        if (router_.holdObject(path, object, space_->objectPose(path.getState(stop), object),
                                               stop, path.getStateCount() - 1, goal,
                                               PathRouter::CONNECT_ITERATIONS, rng, ptc))
                            return true;
                }
        }
        return false;
    }

    unsigned int ManipulationSimplifier::shortenPushes(
        ManipulationPath &path, const ompl::base::Goal *goal, ompl::RNG &rng,
        const ompl::base::PlannerTerminationCondition &ptc) const
    {
        struct Run
        {
            unsigned int object;
            std::size_t first, end;
        };
        std::vector<Run> runs;
        for (unsigned int object = 0; object < space_->objectCount(); ++object)
            for (const auto &[first, end] : pushRuns(path, object))
                runs.push_back({object, first, end});
        // the last run first: a change replaces the states from inside its run on, so the runs
        // before it keep their indices
        std::sort(runs.begin(), runs.end(), [](const Run &a, const Run &b) { return a.first > b.first; });
        unsigned int shortened = 0;
        for (const Run &run : runs)
        {
            if (ptc)
                break;
            // the object stays where the run found it at waypoint `stop` for the rest of the way
            const double length = path.toolPathLength();
            const auto heldFrom = [&](std::size_t stop, ManipulationPath &held)
            {
                const ObjectPose pose = space_->objectPose(path.getState(stop), run.object);
                return router_.holdObject(held, run.object, pose, stop, path.getStateCount() - 1, goal,
                                          SHORTER_PUSH_CONNECT_ITERATIONS, rng, ptc) &&
                       held.toolPathLength() <= length;
            };
            // no push at all first; else bisect for the earliest waypoint of the run that will do
            // (the run's end, the push as it is, always does)
            ManipulationPath best(path);
            const bool dropped = heldFrom(run.first, best);
            bool found = dropped;
            for (std::size_t fails = run.first, does = run.end; !dropped && does - fails > 1 && !ptc;)
            {
                const std::size_t middle = fails + (does - fails) / 2;
                ManipulationPath held(path);
                if (heldFrom(middle, held))
                {
                    best = held;
                    found = true;
                    does = middle;
                }
                else
                    fails = middle;
            }
            if (found)
            {
                path = best;
                ++shortened;
            }
        }
        return shortened;
    }

    bool ManipulationSimplifier::replanWindow(ManipulationPath &path, std::size_t first, std::size_t last,
                                              ompl::RNG &rng,
                                              const ompl::base::PlannerTerminationCondition &ptc) const
    {
        Trajectory replanned(space_);
        const EmptySpacePlanner::Outcome outcome =
            planner_.plan(path.getState(first), path.getState(last), replanned, rng, ptc, true);
        if (outcome == EmptySpacePlanner::Outcome::AlreadyThere)
            replanned.append(path.getState(last), {PrimitiveKind::Transit, -1});
        else if (outcome != EmptySpacePlanner::Outcome::Reached)
            return false;
        if (toolTravel(replanned) >= path.toolPathLength(first, last) - 1e-9 || !isValid(replanned))
            return false;
        // a chain that pushes an object on where a push outside the window brings it back is no gain
        ManipulationPath changed(path);
        changed.replace(first, last, replanned);
        if (changed.pushReversals().size() > path.pushReversals().size())
            return false;
        path = changed;
        return true;
    }

    void ManipulationSimplifier::shortenStretches(ManipulationPath &path, ompl::RNG &rng,
                                                  const ompl::base::PlannerTerminationCondition &ptc) const
    {
        if (!pushesSimulated_)
        {
            shortenWithOMPL(path, rng, ptc);
            return;
        }
        // the stretches between push runs, the last first: a change moves only the states after it
        std::size_t end = path.getStateCount() - 1;
        while (end > 0 && !ptc)
        {
            std::size_t first = end;
            while (first > 0 && path.label(first - 1).kind != PrimitiveKind::Push)
                --first;
            if (end - first >= 2)
            {
                ManipulationPath stretch = subPath(path, first, end);
                const double before = stretch.toolPathLength();
                shortenWithOMPL(stretch, rng, ptc);
                if (stretch.toolPathLength() < before)
                    path.replace(first, end, asTrajectory(stretch, space_));
            }
            end = first;
            while (end > 0 && path.label(end - 1).kind == PrimitiveKind::Push)
                --end;
        }
    }

    void ManipulationSimplifier::shortenWithOMPL(ManipulationPath &path, ompl::RNG &rng,
                                                 const ompl::base::PlannerTerminationCondition &ptc) const
    {
        // OMPL's own shortcutting and smoothing is safe here, since the motion validator accepts
        // only primitives' motions and the path relabels what it changes. Its steps, not
        // simplifyMax(), whose repair of a motion that fails a recheck samples random states in
        // place (objects and all); a copy, kept only when all of it checks at the resolution
        ManipulationPath shorter(path);
        SeededPathSimplifier simplifier(si_, rng.uniformInt(1, std::numeric_limits<int>::max()));
        shortcutPasses(simplifier, shorter, ptc);
        if (!ptc)
            simplifier.smoothBSpline(shorter, 3, shorter.length() / 100.0);
        if (!ptc)
            simplifier.reduceVertices(shorter);
        // OMPL's collapseCloseVertices() as a step of our own that stops at ptc (OMPL's can run
        // for a tenth of a second past it on a long path)
        if (!ptc)
            collapseCloseStates(shorter, ptc);
        // a check stopped by ptc fails, so the copy is kept only when all of it was checked
        if (!ptc && shorter.check() && shorter.toolPathLength() < path.toolPathLength())
            path = shorter;
    }

    void ManipulationSimplifier::shortcut(ManipulationPath &path, ompl::RNG &rng,
                                          const ompl::base::PlannerTerminationCondition &ptc) const
    {
        SeededPathSimplifier simplifier(si_, rng.uniformInt(1, std::numeric_limits<int>::max()));
        shortcutPasses(simplifier, path, ptc);
    }

    bool ManipulationSimplifier::isValid(const Trajectory &trajectory) const
    {
        for (std::size_t k = 0; k + 1 < trajectory.size(); ++k)
            if (!si_->checkMotion(trajectory.state(k), trajectory.state(k + 1)))
                return false;
        return true;
    }
}  // namespace ompl_mm
