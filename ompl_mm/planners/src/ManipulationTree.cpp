#include "ompl_mm/planners/ManipulationTree.h"

#include <cassert>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        /** Squared distance from x to the box [low, high] in n dimensions (0 inside). */
        double squaredBoxDistance(const double *low, const double *high, const double *x, std::size_t n)
        {
            double sum = 0.0;
            for (std::size_t k = 0; k < n; ++k)
            {
                const double below = low[k] - x[k];
                const double above = x[k] - high[k];
                const double out = std::max({below, above, 0.0});
                sum += out * out;
            }
            return sum;
        }
    }  // namespace

    ManipulationTree::ManipulationTree(const ManipulationStateSpace *space, const ManipulationMetric *metric,
                                       bool forward)
        : space_(space), metric_(metric), forward_(forward)
    {
    }

    ManipulationTree::~ManipulationTree()
    {
        clear();
    }

    int ManipulationTree::add(const ompl::base::State *state, int parent, SegmentLabel label, bool branchable)
    {
        assert(parent < static_cast<int>(vertices_.size()));
        const int index = static_cast<int>(vertices_.size());
        Vertex vertex{space_->cloneState(state), parent, label, groups_.size()};
        if (!branchable)
        {
            vertex.group = NO_GROUP;
            vertices_.push_back(vertex);
            roots_ += parent < 0 ? 1 : 0;
            return index;
        }
        metric_->makePoint(vertex.state, point_);
        if (parent < 0 || vertices_[parent].group == NO_GROUP ||
            space_->anyObjectMoves(state, vertices_[parent].state))
            groups_.push_back({point_, {}, {}, newBounds()});
        else
            vertex.group = vertices_[parent].group;
        Group &group = groups_[vertex.group];
        group.members.push_back(index);
        vertices_.push_back(vertex);
        // against the group's objects, which the scan uses for all members
        const std::size_t stride = metric_->packedVertexSize();
        group.packed.resize(group.members.size() * stride);
        double *packed = group.packed.data() + group.packed.size() - stride;
        metric_->packVertex(point_, group.objects, packed);
        extendBounds(group.bounds, point_, packed);
        // a group's members share its objects' configuration: their packed data lie side by side
        assert(group.packed.size() == group.members.size() * stride);
        if (parent < 0)
            ++roots_;
        return index;
    }

    void ManipulationTree::removeLast()
    {
        if (vertices_.back().parent < 0)
            --roots_;
        if (vertices_.back().group == NO_GROUP)
        {
            space_->freeState(vertices_.back().state);
            vertices_.pop_back();
            return;
        }
        // bounds may stay larger than the members: still valid
        Group &group = groups_[vertices_.back().group];
        group.members.pop_back();
        group.packed.resize(group.members.size() * metric_->packedVertexSize());
        if (group.members.empty())
        {
            boxes_.resize(group.bounds);
            groups_.pop_back();
        }
        space_->freeState(vertices_.back().state);
        vertices_.pop_back();
    }

    void ManipulationTree::clear()
    {
        while (!vertices_.empty())
            removeLast();
        boxes_.clear();
    }

    ManipulationTree::Bounds ManipulationTree::newBounds()
    {
        const std::size_t dof = space_->robotDimension();
        const Bounds bounds = boxes_.size();
        const double inf = std::numeric_limits<double>::infinity();
        // empty boxes: lows at +inf, highs at -inf
        for (std::size_t k = 0; k < dof; ++k)
            boxes_.push_back(inf);
        for (std::size_t k = 0; k < dof; ++k)
            boxes_.push_back(-inf);
        boxes_.insert(boxes_.end(), {inf, inf, inf, -inf, -inf, -inf});
        boxes_.insert(boxes_.end(), space_->objectCount(), inf);
        return bounds;
    }

    void ManipulationTree::extendBounds(Bounds bounds, const MetricPoint &point, const double *packed)
    {
        const std::size_t dof = point.joints.size();
        double *box = boxes_.data() + bounds;
        for (std::size_t k = 0; k < dof; ++k)
        {
            box[k] = std::min(box[k], point.joints[k]);
            box[dof + k] = std::max(box[dof + k], point.joints[k]);
        }
        for (int k = 0; k < 3; ++k)
        {
            box[2 * dof + k] = std::min(box[2 * dof + k], point.tool[k]);
            box[2 * dof + 3 + k] = std::max(box[2 * dof + 3 + k], point.tool[k]);
        }
        const double *toObjects = metric_->packedToolToObjects(packed);
        for (std::size_t i = 0; i < space_->objectCount(); ++i)
            box[2 * dof + 6 + i] = std::min(box[2 * dof + 6 + i], toObjects[i]);
    }

    double ManipulationTree::objectAndRobotBound(std::size_t g, const ManipulationMetric::Query &query) const
    {
        if (!query.robotDefined)
            return groupCosts_[g].bound;
        const std::size_t dof = query.point.joints.size();
        const double *box = boxes_.data() + groups_[g].bounds;
        const double joints = std::sqrt(squaredBoxDistance(box, box + dof, query.point.joints.data(), dof));
        const double tool =
            metric_->boundUsesToolDistance()
                ? std::sqrt(squaredBoxDistance(box + 2 * dof, box + 2 * dof + 3, query.point.tool.data(), 3))
                : 0.0;
        return groupCosts_[g].bound + metric_->robotLowerBound(query, joints, tool);
    }

    double ManipulationTree::legBound(std::size_t g, const ManipulationMetric::Query &query) const
    {
        const double *tools = boxes_.data() + groups_[g].bounds + 2 * query.point.joints.size();
        const Eigen::AlignedBox3d toolBox(Eigen::Map<const Eigen::Vector3d>(tools),
                                          Eigen::Map<const Eigen::Vector3d>(tools + 3));
        return metric_->legLowerBound(query, groupCosts_[g], toolBox, tools + 6);
    }

    bool ManipulationTree::mayBeat(std::size_t g, const ManipulationMetric::Query &query, double best) const
    {
        // the bounds add their terms in another order than the distances: rounding may lift a
        // bound a little above the distance it bounds, which the slack absorbs
        const double slack = best * (1.0 + 1e-9);
        // the cheap part first: often it already reaches the best distance
        return groupBounds_[g] < slack && groupBounds_[g] + legBound(g, query) < slack;
    }

    void ManipulationTree::scanGroup(std::size_t g, const ManipulationMetric::Query &query, int *best,
                                     double *bestDistance) const
    {
        const Group &group = groups_[g];
        legPlan_.planned = 0;
        const int m = metric_->nearest(group.packed.data(), group.members.size(), group.objects, query,
                                       groupCosts_[g], legPlan_, bestDistance);
        if (m >= 0)
            *best = group.members[m];
    }

    int ManipulationTree::nearest(const ManipulationMetric::Query &query, double *distance,
                                  double cutoff) const
    {
        int best = -1;
        double bestDistance = cutoff;
        // the most promising group first, so that its distance prunes the others
        groupCosts_.resize(groups_.size());
        groupBounds_.resize(groups_.size());
        std::size_t first = 0;
        for (std::size_t g = 0; g < groups_.size(); ++g)
        {
            groupCosts_[g] = metric_->objectCost(groups_[g].objects, query);
            groupBounds_[g] = objectAndRobotBound(g, query);
            if (groupBounds_[g] < groupBounds_[first])
                first = g;
        }
        if (!groups_.empty() && mayBeat(first, query, bestDistance))
            scanGroup(first, query, &best, &bestDistance);
        for (std::size_t g = 0; g < groups_.size(); ++g)
            if (g != first && mayBeat(g, query, bestDistance))
                scanGroup(g, query, &best, &bestDistance);
        if (distance)
            *distance = bestDistance;
        return best;
    }

    std::vector<int> ManipulationTree::branch(int i) const
    {
        std::vector<int> indices;
        for (; i >= 0; i = vertices_[i].parent)
            indices.push_back(i);
        if (forward_)
            std::reverse(indices.begin(), indices.end());
        return indices;
    }
}  // namespace ompl_mm
