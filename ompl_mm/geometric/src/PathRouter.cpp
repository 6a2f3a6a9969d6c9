#include "ompl_mm/geometric/PathRouter.h"

#include <optional>
#include <utility>

namespace ompl_mm
{
    PathRouter::PathRouter(const ompl::base::SpaceInformationPtr &si,
                           std::shared_ptr<ManipulationMotionValidator> validator)
        : si_(si),
          space_(si->getStateSpace()->as<ManipulationStateSpace>()),
          validator_(std::move(validator)),
          connector_(si)
    {
    }

    bool PathRouter::holdObject(ManipulationPath &path, unsigned int object, const ObjectPose &pose,
                                std::size_t first, std::size_t last, const ompl::base::Goal *goal,
                                unsigned int routeIterations, ompl::RNG &rng,
                                const ompl::base::PlannerTerminationCondition &ptc) const
    {
        std::vector<ompl::base::State *> held;
        appendHeld(path, first, last, object, pose, held);
        const bool endKept =
            last + 1 < path.getStateCount() || space_->equalStates(held.back(), path.getState(last));
        // the end decides before any routing is tried
        if (!(endKept || (goal && goal->isSatisfied(held.back()))))
        {
            freeAll(held);
            return false;
        }
        // the robot's old motions meet the held object where it was pushed before
        return replaceRouted(path, first, last, held, routeIterations, rng, ptc);
    }

    void PathRouter::appendHeld(const ManipulationPath &path, std::size_t first, std::size_t last,
                                unsigned int object, const ObjectPose &pose,
                                std::vector<ompl::base::State *> &states) const
    {
        for (std::size_t k = first; k <= last; ++k)
        {
            states.push_back(si_->cloneState(path.getState(k)));
            space_->setObjectPose(states.back(), object, pose);
        }
    }

    void PathRouter::appendCopies(const Trajectory &trajectory, std::size_t first,
                                  std::vector<ompl::base::State *> &states) const
    {
        for (std::size_t k = first; k < trajectory.size(); ++k)
            states.push_back(si_->cloneState(trajectory.state(k)));
    }

    void PathRouter::freeAll(std::vector<ompl::base::State *> &states) const
    {
        for (ompl::base::State *state : states)
            si_->freeState(state);
        states.clear();
    }

    bool PathRouter::replaceRouted(ManipulationPath &path, std::size_t first, std::size_t last,
                                   std::vector<ompl::base::State *> &states, unsigned int routeIterations,
                                   ompl::RNG &rng, const ompl::base::PlannerTerminationCondition &ptc) const
    {
        Trajectory result(space_);
        const bool routed = routeThrough(states, result, routeIterations, rng, ptc);
        freeAll(states);
        if (routed)
            path.replace(first, last, result);
        return routed;
    }

    bool PathRouter::routeThrough(const std::vector<ompl::base::State *> &states, Trajectory &result,
                                  unsigned int routeIterations, ompl::RNG &rng,
                                  const ompl::base::PlannerTerminationCondition &ptc) const
    {
        result.reset(states[0]);
        for (std::size_t k = 0; k + 1 < states.size();)
        {
            if (ptc)
                return false;
            const std::optional<SegmentLabel> label = validator_->explain(states[k], states[k + 1]);
            if (label && si_->checkMotion(states[k], states[k + 1]))
            {
                result.append(states[k + 1], *label);
                ++k;
                continue;
            }
            // route the robot to the next valid state that only the robot's motions lead to
            std::size_t next = k + 1;
            while (next < states.size() && !space_->anyObjectMoves(states[k], states[next]) &&
                   !si_->isValid(states[next]))
                ++next;
            if (next == states.size() || space_->anyObjectMoves(states[k], states[next]) ||
                !connector_.connect(result, states[next], routeIterations, rng, ptc))
                return false;
            k = next;
        }
        return true;
    }
}  // namespace ompl_mm
