#include "ompl_mm/geometric/PushReversalRemover.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace ompl_mm
{
    namespace
    {
        // directions, in degrees from the earlier push's, in which a push that would reverse it
        // pushes its object aside instead (none against the earlier push)
        constexpr double ASIDE_ANGLES[] = {-90.0, -60.0, -30.0, 0.0, 30.0, 60.0, 90.0};
        // RRT iterations of the robot's routes past an object pushed aside: more than after a
        // round trip, as the object aside often narrows the robot's old way to a passage
        constexpr unsigned int ASIDE_ROUTE_ITERATIONS = 5000;

        /** True when path's segment k pushes object. */
        bool pushes(const ManipulationPath &path, std::size_t k, unsigned int object)
        {
            return path.label(k).kind == PrimitiveKind::Push &&
                   path.label(k).object == static_cast<int>(object);
        }

        /** The state after the run of pushes of object that segment k is in. */
        std::size_t afterPushRun(const ManipulationPath &path, std::size_t k, unsigned int object)
        {
            std::size_t end = k + 1;
            while (end < path.getStateCount() - 1 && pushes(path, end, object))
                ++end;
            return end;
        }
    }  // namespace

    PushReversalRemover::PushReversalRemover(const ompl::base::SpaceInformationPtr &si,
                                             const std::shared_ptr<ManipulationMotionValidator> &validator)
        : si_(si),
          space_(si->getStateSpace()->as<ManipulationStateSpace>()),
          router_(si, validator),
          planner_(space_, validator ? validator->primitives() : std::vector<PrimitivePtr>())
    {
    }

    unsigned int PushReversalRemover::remove(ManipulationPath &path, const ompl::base::Goal *goal,
                                             ompl::RNG &rng,
                                             const ompl::base::PlannerTerminationCondition &ptc) const
    {
        // the last reversal first: a change replaces states from its earlier push on, so each
        // reversal is tried once, those before it keeping their indices
        unsigned int removed = 0;
        std::size_t before = path.getStateCount();
        while (!ptc)
        {
            const std::vector<ManipulationPath::PushReversal> reversals = path.pushReversals();
            std::optional<ManipulationPath::PushReversal> last;
            for (const ManipulationPath::PushReversal &reversal : reversals)
                if (reversal.earlier < before)
                    last = reversal;
            if (!last)
                break;
            // the earlier push run ended early; else the object pushed on at once to
            // where the later pushes leave it; else the later run pushing it aside: the first way
            // after which the path has fewer reversals (a way's new pushes may reverse too), else
            // the first after which it has as many, the reversal now earlier, where the loop
            // goes on
            const std::size_t count = reversals.size();
            const std::function<bool(ManipulationPath &)> ways[] = {
                [&](ManipulationPath &p) { return endReversal(p, *last, rng, ptc); },
                [&](ManipulationPath &p) { return pushOnceInstead(p, *last, rng, ptc); },
                [&](ManipulationPath &p) { return pushAside(p, *last, goal, rng, ptc); }};
            std::optional<ManipulationPath> asMany;
            bool fewer = false;
            for (const auto &way : ways)
            {
                ManipulationPath changed(path);
                if (!way(changed))
                    continue;
                const std::size_t left = changed.pushReversals().size();
                if (left < count)
                {
                    path = changed;
                    fewer = true;
                    break;
                }
                if (left == count && !asMany)
                    asMany.emplace(std::move(changed));
            }
            if (fewer)
                ++removed;
            else if (asMany)
                path = *asMany;
            before = last->earlier;
        }
        return removed;
    }

    bool PushReversalRemover::endReversal(ManipulationPath &path,
                                          const ManipulationPath::PushReversal &reversal, ompl::RNG &rng,
                                          const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const std::size_t later = reversal.later;
        const unsigned int object = reversal.object;
        const ompl::base::State *afterLater = path.getState(later + 1);
        const Eigen::Vector3d wanted = space_->objectPosition(afterLater, object);
        // the earlier push run (its segments first … reversal.earlier) ends where it comes nearest
        // to where the later push leaves the object: in segment `cut`, at t along it
        std::size_t first = reversal.earlier;
        while (first > 0 && pushes(path, first - 1, object))
            --first;
        std::size_t cut = first;
        double t = 0.0;
        double nearest = (space_->objectPosition(path.getState(first), object) - wanted).norm();
        for (std::size_t k = first; k <= reversal.earlier; ++k)
        {
            const Eigen::Vector3d from = space_->objectPosition(path.getState(k), object);
            const Eigen::Vector3d direction = space_->objectPosition(path.getState(k + 1), object) - from;
            if (direction.squaredNorm() == 0.0)
                continue;
            const double along =
                std::clamp((wanted - from).dot(direction) / direction.squaredNorm(), 0.0, 1.0);
            const double distance = (from + along * direction - wanted).norm();
            if (distance < nearest)
            {
                nearest = distance;
                cut = k;
                t = along;
            }
        }
        std::vector<ompl::base::State *> states;
        for (std::size_t k = first; k <= cut; ++k)
            states.push_back(si_->cloneState(path.getState(k)));
        if (t > 0.0)
        {
            states.push_back(si_->allocState());
            space_->interpolate(path.getState(cut), path.getState(cut + 1), t, states.back());
        }
        // on the later push's line the object is where that push ends (to rounding, which no
        // motion counts as moving it), and the empty-space planner below then only moves the robot
        const ObjectPose held = space_->objectPose(states.back(), object);
        // the object stays there until the later push, which then starts from there
        router_.appendHeld(path, cut + 1, later, object, held, states);
        Trajectory push(space_);
        const EmptySpacePlanner::Outcome outcome =
            planner_.plan(states.back(), afterLater, push, rng, ptc, true);
        router_.appendCopies(push, 1, states);
        if (outcome == EmptySpacePlanner::Outcome::AlreadyThere)
            states.push_back(si_->cloneState(afterLater));
        if (outcome != EmptySpacePlanner::Outcome::Reached &&
            outcome != EmptySpacePlanner::Outcome::AlreadyThere)
        {
            router_.freeAll(states);
            return false;
        }
        return router_.replaceRouted(path, first, later + 1, states, PathRouter::CONNECT_ITERATIONS, rng,
                                     ptc);
    }

    bool PushReversalRemover::pushOnceInstead(ManipulationPath &path,
                                              const ManipulationPath::PushReversal &reversal, ompl::RNG &rng,
                                              const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const unsigned int object = reversal.object;
        const std::size_t end = afterPushRun(path, reversal.later, object);
        const ObjectPose left = space_->objectPose(path.getState(end), object);
        // from where the earlier push begins, the object pushed there (the robot ending anywhere)
        ompl::base::State *target = si_->cloneState(path.getState(reversal.earlier));
        space_->setObjectPose(target, object, left);
        Trajectory push(space_);
        const bool pushed = planner_.plan(path.getState(reversal.earlier), target, push, rng, ptc, true) ==
                                EmptySpacePlanner::Outcome::Partial ||
                            space_->equalStates(push.back(), target);
        si_->freeState(target);
        if (!pushed || space_->objectMoves(push.back(), path.getState(end), object))
            return false;
        // then the robot's old way on, the object staying there, routed around it
        std::vector<ompl::base::State *> states;
        router_.appendCopies(push, 0, states);
        router_.appendHeld(path, reversal.earlier + 1, end, object, left, states);
        return router_.replaceRouted(path, reversal.earlier, end, states, PathRouter::CONNECT_ITERATIONS, rng,
                                     ptc);
    }

    bool PushReversalRemover::pushAside(ManipulationPath &path,
                                        const ManipulationPath::PushReversal &reversal,
                                        const ompl::base::Goal *goal, ompl::RNG &rng,
                                        const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const unsigned int object = reversal.object;
        const std::size_t later = reversal.later;
        const std::size_t last = path.getStateCount() - 1;
        const std::size_t end = afterPushRun(path, later, object);
        const ompl::base::State *from = path.getState(later);
        const Eigen::Vector3d there = space_->objectPosition(from, object);
        const Eigen::Vector3d wanted = space_->objectPosition(path.getState(end), object) - there;
        const Eigen::Vector3d earlierPush =
            space_->objectPosition(path.getState(reversal.earlier + 1), object) -
            space_->objectPosition(path.getState(reversal.earlier), object);
        // as far as the later run pushes, or the earlier push, in the directions nearest to the
        // later run's first
        std::vector<Eigen::Vector3d> directions;
        for (const double degrees : ASIDE_ANGLES)
            directions.push_back(Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
                                 earlierPush.normalized());
        std::stable_sort(directions.begin(), directions.end(),
                         [&](const Eigen::Vector3d &a, const Eigen::Vector3d &b)
                         { return a.dot(wanted) > b.dot(wanted); });
        std::vector<Eigen::Vector3d> moves;
        for (const double distance : {wanted.norm(), earlierPush.norm()})
            for (const Eigen::Vector3d &direction : directions)
                moves.push_back(distance * direction);
        ompl::base::State *target = si_->cloneState(from);
        Trajectory push(space_);
        bool changed = false;
        for (std::size_t i = 0; i < moves.size() && !changed && !ptc; ++i)
        {
            ObjectPose aside = space_->objectPose(from, object);
            aside.position += moves[i];
            space_->setObjectPose(target, object, aside);
            const EmptySpacePlanner::Outcome outcome = planner_.plan(from, target, push, rng, ptc, true);
            if ((outcome != EmptySpacePlanner::Outcome::Partial &&
                 !space_->equalStates(push.back(), target)) ||
                space_->objectMoves(push.back(), target, object))
                continue;
            // then the robot's old way on, the object staying there, routed around it
            std::vector<ompl::base::State *> states;
            router_.appendCopies(push, 0, states);
            router_.appendHeld(path, later + 1, last, object, aside, states);
            if (!goal || !goal->isSatisfied(states.back()))
                router_.freeAll(states);
            else
                changed = router_.replaceRouted(path, later, last, states, ASIDE_ROUTE_ITERATIONS, rng, ptc);
        }
        si_->freeState(target);
        return changed;
    }
}  // namespace ompl_mm
