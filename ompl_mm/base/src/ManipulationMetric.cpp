#include "ompl_mm/base/ManipulationMetric.h"

#include <ompl/util/Exception.h>

#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        constexpr double SAME = 1e-9;

        bool moves(const MetricPoint &a, const MetricPoint &b, std::size_t i)
        {
            return (a.objects[i] - b.objects[i]).cwiseAbs().maxCoeff() > SAME ||
                   std::abs(a.yaws[i] - b.yaws[i]) > SAME;
        }

        double jointDistance(const MetricPoint &a, const MetricPoint &b)
        {
            double sum = 0.0;
            for (std::size_t j = 0; j < a.joints.size(); ++j)
                sum += (a.joints[j] - b.joints[j]) * (a.joints[j] - b.joints[j]);
            return std::sqrt(sum);
        }
    }  // namespace

    ManipulationMetric::ManipulationMetric(const ManipulationStateSpace *space)
        : space_(space), mobile_(space->model()->isMobileBase())
    {
        if (space->objectCount() > MAX_OBJECTS)
            throw ompl::Exception("ManipulationMetric: at most " + std::to_string(MAX_OBJECTS) +
                                  " objects, got " + std::to_string(space->objectCount()));
    }

    void ManipulationMetric::makePoint(const ompl::base::State *state, MetricPoint &point) const
    {
        const double *q = space_->robotValues(state);
        point.joints.assign(q, q + space_->robotDimension());
        const Eigen::Isometry3d tool = space_->model()->toolFrame(q);
        point.tool = tool.translation();
        point.toolRotation = Eigen::Quaterniond(tool.linear());
        point.objects.resize(space_->objectCount());
        point.yaws.resize(space_->objectCount());
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            point.objects[i] = space_->objectPosition(state, i);
            point.yaws[i] = space_->objectYaw(state, i);
        }
    }

    double ManipulationMetric::robotTerm(const MetricPoint &from, const MetricPoint &to) const
    {
        if (mobile_)
            return jointDistance(from, to);
        const double rotation = 1.0 - std::abs(from.toolRotation.dot(to.toolRotation));
        return weights_.robotWeight *
               (0.5 * jointDistance(from, to) + (from.tool - to.tool).norm() + 2.0 * rotation);
    }

    double ManipulationMetric::addToolLegs(const MetricPoint &from, const MetricPoint &to,
                                           std::uint64_t moving, const Eigen::Vector3d &startTool,
                                           const Eigen::Vector3d &targetTool, double cost,
                                           double cutoff) const
    {
        if (moving == 0)
            return cost;
        Eigen::Vector3d tool = startTool;
        while (moving != 0)
        {
            if (cost >= cutoff)
                return std::numeric_limits<double>::infinity();
            int next = 0;
            double nearest = std::numeric_limits<double>::infinity();
            for (std::uint64_t rest = moving; rest != 0; rest &= rest - 1)
            {
                const int i = __builtin_ctzll(rest);
                const double d = (from.objects[i] - tool).squaredNorm();
                if (d < nearest)
                {
                    nearest = d;
                    next = i;
                }
            }
            moving &= ~(std::uint64_t{1} << next);
            cost += approachCost(std::sqrt(nearest));
            tool = to.objects[next];
        }
        cost += (targetTool - tool).norm();
        return cost < cutoff ? cost : std::numeric_limits<double>::infinity();
    }

    double ManipulationMetric::approachCost(double distance) const
    {
        return distance > weights_.contactDistance
                   ? weights_.moveToObjectPenalty + weights_.moveToObjectFactor * distance
                   : 0.0;
    }

    double ManipulationMetric::legLowerBound(const MetricPoint &objects, const Query &query,
                                             const ObjectCost &objectCost,
                                             const Eigen::AlignedBox3d &toolBox) const
    {
        if (objectCost.moving == 0)
            return 0.0;
        // the tool starts at the vertex (forward, or undefined robot) or at the sample, and ends
        // at the sample (forward with a defined robot) or at the vertex
        const MetricPoint &from = query.sampleIsTarget ? objects : query.point;
        const MetricPoint &to = query.sampleIsTarget ? query.point : objects;
        const bool startsAtVertex = query.sampleIsTarget || !query.robotDefined;
        const bool endsAtVertex = !query.sampleIsTarget || !query.robotDefined;
        double first = std::numeric_limits<double>::infinity();
        double last = std::numeric_limits<double>::infinity();
        for (std::uint64_t rest = objectCost.moving; rest != 0; rest &= rest - 1)
        {
            const int i = __builtin_ctzll(rest);
            first = std::min(first, startsAtVertex ? toolBox.squaredExteriorDistance(from.objects[i])
                                                   : (from.objects[i] - query.point.tool).squaredNorm());
            last = std::min(last, endsAtVertex ? toolBox.squaredExteriorDistance(to.objects[i])
                                               : (to.objects[i] - query.point.tool).squaredNorm());
        }
        return approachCost(std::sqrt(first)) + std::sqrt(last);
    }

    ManipulationMetric::ObjectCost ManipulationMetric::objectCost(const MetricPoint &objects,
                                                                  const Query &query) const
    {
        ObjectCost cost;
        for (std::size_t i = 0; i < objects.objects.size(); ++i)
            if (query.objectDefined[i] && moves(objects, query.point, i))
            {
                cost.moving |= std::uint64_t{1} << i;
                cost.bound +=
                    weights_.movingObjectPenalty + (objects.objects[i] - query.point.objects[i]).norm();
            }
        return cost;
    }

    double ManipulationMetric::robotLowerBound(const Query &query, double jointDistance,
                                               double toolDistance) const
    {
        if (!query.robotDefined)
            return 0.0;
        return mobile_ ? jointDistance : weights_.robotWeight * (0.5 * jointDistance + toolDistance);
    }

    double ManipulationMetric::distance(const MetricPoint &from, const MetricPoint &to) const
    {
        double cost = robotTerm(from, to);
        std::uint64_t moving = 0;
        for (std::size_t i = 0; i < from.objects.size(); ++i)
            if (moves(from, to, i))
            {
                moving |= std::uint64_t{1} << i;
                cost += weights_.movingObjectPenalty + (to.objects[i] - from.objects[i]).norm();
            }
        return addToolLegs(from, to, moving, from.tool, to.tool, cost,
                           std::numeric_limits<double>::infinity());
    }

    void ManipulationMetric::makeQuery(const PartialState &sample, bool sampleIsTarget, Query &query) const
    {
        makePoint(sample.state(), query.point);
        query.objectDefined.resize(space_->objectCount());
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            query.objectDefined[i] = sample.objectDefined(i);
        query.robotDefined = sample.robotDefined();
        query.sampleIsTarget = sampleIsTarget;
    }

    double ManipulationMetric::distance(const MetricPoint &vertex, const Query &query,
                                        const ObjectCost &objectCost, double cutoff) const
    {
        const MetricPoint &from = query.sampleIsTarget ? vertex : query.point;
        const MetricPoint &to = query.sampleIsTarget ? query.point : vertex;
        // an undefined robot takes the vertex's pose: no robot term, and the tool starts and ends there
        if (!query.robotDefined)
            return addToolLegs(from, to, objectCost.moving, vertex.tool, vertex.tool, objectCost.bound,
                               cutoff);
        const double cost = robotTerm(from, to) + objectCost.bound;
        if (cost >= cutoff)
            return std::numeric_limits<double>::infinity();
        return addToolLegs(from, to, objectCost.moving, from.tool, to.tool, cost, cutoff);
    }
}  // namespace ompl_mm
