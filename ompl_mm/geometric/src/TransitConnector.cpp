#include "ompl_mm/geometric/TransitConnector.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        double jointDistance(const ManipulationStateSpace &space, const ompl::base::State *a,
                             const ompl::base::State *b)
        {
            const double *qa = space.robotValues(a);
            const double *qb = space.robotValues(b);
            double squared = 0.0;
            for (unsigned int j = 0; j < space.robotDimension(); ++j)
                squared += (qa[j] - qb[j]) * (qa[j] - qb[j]);
            return std::sqrt(squared);
        }
    }  // namespace

    TransitConnector::TransitConnector(ompl::base::SpaceInformationPtr si)
        : si_(std::move(si)),
          space_(si_->getStateSpace()->as<ManipulationStateSpace>()),
          range_(0.1 * space_->getSubspace(0)->getMaximumExtent())
    {
    }

    int TransitConnector::nearest(const Tree &tree, const ompl::base::State *state) const
    {
        int best = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < tree.size(); ++i)
        {
            const double d = jointDistance(*space_, tree[i].state, state);
            if (d < bestDistance)
            {
                bestDistance = d;
                best = static_cast<int>(i);
            }
        }
        return best;
    }

    int TransitConnector::extend(Tree &tree, const ompl::base::State *target) const
    {
        const int near = nearest(tree, target);
        const double d = jointDistance(*space_, tree[near].state, target);
        ompl::base::State *next = si_->allocState();
        space_->interpolate(tree[near].state, target, d > range_ ? range_ / d : 1.0, next);
        if (!si_->checkMotion(tree[near].state, next))
        {
            si_->freeState(next);
            return -1;
        }
        tree.push_back({next, near});
        return static_cast<int>(tree.size()) - 1;
    }

    std::vector<const ompl::base::State *> TransitConnector::branch(const Tree &tree, int node)
    {
        std::vector<const ompl::base::State *> states;
        for (int i = node; i >= 0; i = tree[i].parent)
            states.push_back(tree[i].state);
        std::reverse(states.begin(), states.end());
        return states;
    }

    bool TransitConnector::connect(Trajectory &trajectory, const ompl::base::State *to,
                                   unsigned int maxIterations, ompl::RNG &rng,
                                   const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const SegmentLabel transit{PrimitiveKind::Transit, -1};
        if (si_->checkMotion(trajectory.back(), to))
        {
            trajectory.append(to, transit);
            return true;
        }
        Tree trees[2] = {{{si_->cloneState(trajectory.back()), -1}}, {{si_->cloneState(to), -1}}};
        const auto *bounds = &space_->getSubspace(0)->as<ompl::base::RealVectorStateSpace>()->getBounds();
        ompl::base::State *sample = si_->cloneState(to);
        std::vector<const ompl::base::State *> path;
        for (unsigned int iteration = 0; iteration < maxIterations && path.empty() && !ptc; ++iteration)
        {
            for (unsigned int j = 0; j < space_->robotDimension(); ++j)
                space_->robotValues(sample)[j] = rng.uniformReal(bounds->low[j], bounds->high[j]);
            Tree &grown = trees[iteration % 2];
            Tree &other = trees[1 - iteration % 2];
            const int added = extend(grown, sample);
            if (added < 0)
                continue;
            // connect: the other tree steps towards the new node until it reaches it or is blocked
            int reached = -1;
            for (int last = extend(other, grown[added].state); last >= 0 && !ptc;
                 last = extend(other, grown[added].state))
                if (jointDistance(*space_, other[last].state, grown[added].state) < 1e-12)
                {
                    reached = last;
                    break;
                }
            if (reached < 0)
                continue;
            std::vector<const ompl::base::State *> fromStart =
                branch(trees[0], iteration % 2 == 0 ? added : reached);
            std::vector<const ompl::base::State *> fromGoal =
                branch(trees[1], iteration % 2 == 0 ? reached : added);
            path = fromStart;
            path.insert(path.end(), fromGoal.rbegin() + 1, fromGoal.rend());
        }
        // shorten greedily: from each waypoint to the farthest one it reaches straight
        for (std::size_t i = 0; i + 1 < path.size();)
        {
            std::size_t j = path.size() - 1;
            while (j > i + 1 && !si_->checkMotion(path[i], path[j]))
                --j;
            trajectory.append(path[j], transit);
            i = j;
        }
        const bool connected = !path.empty();
        si_->freeState(sample);
        for (Tree &tree : trees)
            for (Node &node : tree)
                si_->freeState(node.state);
        return connected;
    }
}  // namespace ompl_mm
