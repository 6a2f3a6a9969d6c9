#include "ompl_mm/base/ManipulationMetric.h"

#include <ompl/util/Exception.h>

#include <algorithm>
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

        /** The object of the set `objects` (bits) whose position is nearest to point; its squared
            distance in *squared. @pre objects != 0. */
        int nearestObject(std::uint64_t objects, const std::vector<Eigen::Vector3d> &positions,
                          const Eigen::Vector3d &point, double *squared)
        {
            int nearest = __builtin_ctzll(objects);
            *squared = (positions[nearest] - point).squaredNorm();
            for (std::uint64_t rest = objects & (objects - 1); rest != 0; rest &= rest - 1)
            {
                const int i = __builtin_ctzll(rest);
                const double d = (positions[i] - point).squaredNorm();
                if (d < *squared)
                {
                    *squared = d;
                    nearest = i;
                }
            }
            return nearest;
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

    void ManipulationMetric::packRobot(const MetricPoint &point, double *out) const
    {
        std::copy_n(point.tool.data(), 3, out);
        std::copy_n(point.toolRotation.coeffs().data(), 4, out + 3);
        std::copy(point.joints.begin(), point.joints.end(), out + 7);
    }

    double ManipulationMetric::robotTerm(const double *packedRobot, const MetricPoint &point) const
    {
        const double *joints = packedRobot + 7;
        double squared = 0.0;
        for (std::size_t j = 0; j < point.joints.size(); ++j)
            squared += (joints[j] - point.joints[j]) * (joints[j] - point.joints[j]);
        if (mobile_)
            return std::sqrt(squared);
        const double rotation =
            1.0 -
            std::abs(Eigen::Map<const Eigen::Vector4d>(packedRobot + 3).dot(point.toolRotation.coeffs()));
        const double tool = (Eigen::Map<const Eigen::Vector3d>(packedRobot) - point.tool).norm();
        return weights_.robotWeight * (0.5 * std::sqrt(squared) + tool + 2.0 * rotation);
    }

    void ManipulationMetric::planLegs(const MetricPoint &from, const MetricPoint &to, std::uint64_t moving,
                                      LegPlan &plan) const
    {
        plan.legsAfter.resize(from.objects.size());
        plan.lastEnd.resize(from.objects.size());
        for (std::uint64_t firsts = moving; firsts != 0; firsts &= firsts - 1)
        {
            const int first = __builtin_ctzll(firsts);
            std::uint64_t pending = moving & ~(std::uint64_t{1} << first);
            Eigen::Vector3d tool = to.objects[first];
            double legs = 0.0;
            while (pending != 0)
            {
                double nearest = 0.0;
                const int next = nearestObject(pending, from.objects, tool, &nearest);
                pending &= ~(std::uint64_t{1} << next);
                legs += approachCost(std::sqrt(nearest));
                tool = to.objects[next];
            }
            plan.legsAfter[first] = legs;
            plan.lastEnd[first] = tool;
        }
        plan.ready = true;
    }

    double ManipulationMetric::addToolLegs(const MetricPoint &from, const MetricPoint &to,
                                           std::uint64_t moving, const Eigen::Vector3d &startTool,
                                           const Eigen::Vector3d &targetTool, double cost, double cutoff,
                                           LegPlan &plan) const
    {
        if (moving == 0)
            return cost;
        // the first object is the moving one nearest to the start; the rest of the visit is planned
        double nearest = 0.0;
        const int first = nearestObject(moving, from.objects, startTool, &nearest);
        cost += approachCost(std::sqrt(nearest));
        if (cost >= cutoff)
            return std::numeric_limits<double>::infinity();
        if ((moving & (moving - 1)) == 0)
            cost += (targetTool - to.objects[first]).norm();
        else
        {
            if (!plan.ready)
                planLegs(from, to, moving, plan);
            cost += plan.legsAfter[first] + (targetTool - plan.lastEnd[first]).norm();
        }
        return cost < cutoff ? cost : std::numeric_limits<double>::infinity();
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

    ManipulationMetric::ObjectCost ManipulationMetric::objectCost(const MetricPoint &a, const MetricPoint &b,
                                                                  const std::vector<char> *defined) const
    {
        ObjectCost cost;
        for (std::size_t i = 0; i < a.objects.size(); ++i)
            if ((!defined || (*defined)[i]) && moves(a, b, i))
            {
                cost.moving |= std::uint64_t{1} << i;
                cost.bound += weights_.movingObjectPenalty + (a.objects[i] - b.objects[i]).norm();
            }
        return cost;
    }

    ManipulationMetric::ObjectCost ManipulationMetric::objectCost(const MetricPoint &objects,
                                                                  const Query &query) const
    {
        return objectCost(objects, query.point, &query.objectDefined);
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
        std::vector<double> packed(packedRobotSize());
        packRobot(from, packed.data());
        const ObjectCost objects = objectCost(from, to, nullptr);
        LegPlan plan;
        return addToolLegs(from, to, objects.moving, from.tool, to.tool,
                           robotTerm(packed.data(), to) + objects.bound,
                           std::numeric_limits<double>::infinity(), plan);
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
        std::vector<double> packed(packedRobotSize());
        packRobot(vertex, packed.data());
        LegPlan plan;
        return distance(packed.data(), vertex, query, objectCost, cutoff, plan);
    }

    double ManipulationMetric::distance(const double *packedRobot, const MetricPoint &objects,
                                        const Query &query, const ObjectCost &objectCost, double cutoff,
                                        LegPlan &plan) const
    {
        const MetricPoint &from = query.sampleIsTarget ? objects : query.point;
        const MetricPoint &to = query.sampleIsTarget ? query.point : objects;
        const Eigen::Vector3d vertexTool = Eigen::Map<const Eigen::Vector3d>(packedRobot);
        // an undefined robot takes the vertex's pose: no robot term, and the tool starts and ends there
        if (!query.robotDefined)
            return addToolLegs(from, to, objectCost.moving, vertexTool, vertexTool, objectCost.bound, cutoff,
                               plan);
        const double cost = robotTerm(packedRobot, query.point) + objectCost.bound;
        if (cost >= cutoff)
            return std::numeric_limits<double>::infinity();
        return query.sampleIsTarget ? addToolLegs(from, to, objectCost.moving, vertexTool, query.point.tool,
                                                  cost, cutoff, plan)
                                    : addToolLegs(from, to, objectCost.moving, query.point.tool, vertexTool,
                                                  cost, cutoff, plan);
    }
}  // namespace ompl_mm
