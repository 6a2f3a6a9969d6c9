#include "ompl_mm/primitives/EmptySpacePlanner.h"

#include <algorithm>
#include <numeric>

namespace ompl_mm
{
    EmptySpacePlanner::EmptySpacePlanner(const ManipulationStateSpace *space,
                                         std::vector<PrimitivePtr> primitives)
        : space_(space),
          primitives_(std::move(primitives)),
          order_(primitives_.size()),
          failed_(primitives_.size())
    {
    }

    EmptySpacePlanner::Outcome EmptySpacePlanner::plan(const ompl::base::State *from,
                                                       const ompl::base::State *to, Trajectory &trajectory,
                                                       ompl::RNG &rng,
                                                       const ompl::base::PlannerTerminationCondition &ptc,
                                                       bool exactOnly)
    {
        trajectory.reset(from);
        if (space_->equalStates(from, to))
            return Outcome::AlreadyThere;

        std::iota(order_.begin(), order_.end(), 0);
        for (std::size_t i = order_.size(); i > 1; --i)
            std::swap(order_[i - 1], order_[rng.uniformInt(0, static_cast<int>(i) - 1)]);
        std::fill(failed_.begin(), failed_.end(), 0);

        // what is left to reach: `to`, but with the objects that simulated primitives moved
        // where they left them
        ompl::base::State *target = space_->cloneState(to);
        unsigned int steps = 0;
        bool useful = true;
        bool done = false;
        while (useful && steps < MAX_STEPS && !ptc && !done)
        {
            useful = false;
            for (std::size_t index : order_)
            {
                const Primitive &primitive = *primitives_[index];
                if (failed_[index] || (exactOnly && !primitive.endsWhereAsked()) ||
                    !primitive.isUseful(trajectory.back(), target))
                    continue;
                if (ptc)
                    break;  // out of time: what was found so far
                useful = true;
                ++steps;
                const std::size_t start = trajectory.size() - 1;  // where the primitive begins
                const bool found = primitive.propagate(trajectory.back(), target, trajectory, ptc);
                tally_.attempt(primitive.kind(), found, found ? "" : primitive.takeRejection());
                if (found)
                    std::fill(failed_.begin(), failed_.end(), 0);
                else
                    failed_[index] = 1;
                if (found && !primitive.endsWhereAsked())
                    adoptMovedObjects(trajectory.state(start), trajectory.back(), target);
                // `to` itself, or as near as the simulated primitives came
                done = space_->equalStates(trajectory.back(), target);
                if (done)
                    break;
            }
        }
        const bool reached = done && space_->equalStates(trajectory.back(), to);
        space_->freeState(target);
        if (reached)
            return Outcome::Reached;
        return trajectory.size() > 1 ? Outcome::Partial : Outcome::Failed;
    }

    void EmptySpacePlanner::adoptMovedObjects(const ompl::base::State *before, const ompl::base::State *after,
                                              ompl::base::State *target) const
    {
        for (unsigned int k = 0; k < space_->objectCount(); ++k)
            if (space_->objectMoves(before, after, k))
                space_->setObjectPose(target, k, space_->objectPose(after, k));
    }
}  // namespace ompl_mm
