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
                                                       const ompl::base::PlannerTerminationCondition &ptc)
    {
        trajectory.reset(from);
        if (space_->equalStates(from, to))
            return Outcome::AlreadyThere;

        std::iota(order_.begin(), order_.end(), 0);
        for (std::size_t i = order_.size(); i > 1; --i)
            std::swap(order_[i - 1], order_[rng.uniformInt(0, static_cast<int>(i) - 1)]);
        std::fill(failed_.begin(), failed_.end(), 0);

        unsigned int steps = 0;
        bool useful = true;
        while (useful && steps < MAX_STEPS && !ptc)
        {
            useful = false;
            for (std::size_t index : order_)
            {
                const Primitive &primitive = *primitives_[index];
                if (failed_[index] || !primitive.isUseful(trajectory.back(), to))
                    continue;
                if (ptc)
                    break;  // out of time: what was found so far
                useful = true;
                ++steps;
                const bool found = primitive.propagate(trajectory.back(), to, trajectory, ptc);
                tally_.attempt(primitive.kind(), found, found ? "" : primitive.takeRejection());
                if (found)
                    std::fill(failed_.begin(), failed_.end(), 0);
                else
                    failed_[index] = 1;
                if (space_->equalStates(trajectory.back(), to))
                    return Outcome::Reached;
            }
        }
        return trajectory.size() > 1 ? Outcome::Partial : Outcome::Failed;
    }
}  // namespace ompl_mm
