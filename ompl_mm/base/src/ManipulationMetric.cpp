#include "ompl_mm/base/ManipulationMetric.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        /** The object of the set `objects` (bits) with the smallest squared distance (the first
            such, in index order); that distance in *nearest. @pre objects != 0. */
        int nearestObject(std::uint64_t objects, const double *squared, double *nearest)
        {
            int index = __builtin_ctzll(objects);
            *nearest = squared[index];
            for (std::uint64_t rest = objects & (objects - 1); rest != 0; rest &= rest - 1)
            {
                const int i = __builtin_ctzll(rest);
                if (squared[i] < *nearest)
                {
                    *nearest = squared[i];
                    index = i;
                }
            }
            return index;
        }

        /** Squared distances from point to the objects of the set `objects` (bits) into out. */
        void squaredDistances(std::uint64_t objects, const std::vector<Eigen::Vector3d> &positions,
                              const Eigen::Vector3d &point, double *out)
        {
            for (; objects != 0; objects &= objects - 1)
            {
                const int i = __builtin_ctzll(objects);
                out[i] = (positions[i] - point).squaredNorm();
            }
        }

        /** The set of all n objects, as bits. */
        std::uint64_t allObjects(std::size_t n)
        {
            return n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
        }
    }  // namespace

    ManipulationMetric::ManipulationMetric(const ManipulationStateSpace *space) : space_(space)
    {
        setWeights(defaultWeights(space->model()->robot()));
        if (space->objectCount() > MAX_OBJECTS)
            throw ompl::Exception("ManipulationMetric: at most " + std::to_string(MAX_OBJECTS) +
                                  " objects, got " + std::to_string(space->objectCount()));
    }

    void ManipulationMetric::makePoint(const ompl::base::State *state, MetricPoint &point) const
    {
        const double *q = space_->robotValues(state);
        // weighted once here, so that every distance of these points is the plain Euclidean one
        point.joints.resize(space_->robotDimension());
        for (std::size_t j = 0; j < point.joints.size(); ++j)
            point.joints[j] = jointScales_[j] * q[j];
        const Eigen::Isometry3d tool = space_->model()->toolFrame(q);
        point.tool = tool.translation();
        point.toolRotation = Eigen::Quaterniond(tool.linear());
        point.objects.resize(space_->objectCount());
        point.yaws.resize(space_->objectCount());
        point.displaced = 0;
        const std::vector<MovableObject> &sceneObjects = space_->model()->scene().objects;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            point.objects[i] = space_->objectPosition(state, i);
            point.yaws[i] = space_->objectYaw(state, i);
            const ObjectPose &start = sceneObjects[i].start;
            if (point.objects[i] != start.position || point.yaws[i] != start.yaw)
                point.displaced |= std::uint64_t{1} << i;
        }
    }

    void ManipulationMetric::packVertex(const MetricPoint &point, const MetricPoint &objects,
                                        double *out) const
    {
        std::copy_n(point.tool.data(), 3, out);
        std::copy_n(point.toolRotation.coeffs().data(), 4, out + 3);
        std::copy(point.joints.begin(), point.joints.end(), out + 7);
        squaredDistances(allObjects(objects.objects.size()), objects.objects, point.tool,
                         out + 7 + point.joints.size());
    }

    inline double ManipulationMetric::robotTerm(const double *packedVertex, const MetricPoint &point) const
    {
        const double *joints = packedVertex + 7;
        double squared = 0.0;
        for (std::size_t j = 0; j < point.joints.size(); ++j)
            squared += (joints[j] - point.joints[j]) * (joints[j] - point.joints[j]);
        // robots measured in joint space alone skip the tool's terms (and their cost)
        if (jointDistanceOnly_)
            return std::sqrt(squared);
        const double rotation =
            1.0 -
            std::abs(Eigen::Map<const Eigen::Vector4d>(packedVertex + 3).dot(point.toolRotation.coeffs()));
        const double tool = (Eigen::Map<const Eigen::Vector3d>(packedVertex) - point.tool).norm();
        return weights_.robotWeight *
               (std::sqrt(squared) + weights_.toolWeight * tool + weights_.rotationWeight * rotation);
    }

    void ManipulationMetric::setWeights(const Weights &weights)
    {
        weights_ = weights;
        const RobotModel &robot = space_->model()->robot();
        jointScales_.resize(robot.dof());
        for (unsigned int j = 0; j < robot.dof(); ++j)
            jointScales_[j] = robot.isBaseJoint(j) ? weights.baseWeight : weights.jointWeight;
        jointDistanceOnly_ =
            weights.toolWeight == 0.0 && weights.rotationWeight == 0.0 && weights.robotWeight == 1.0;
    }

    ManipulationMetric::Weights ManipulationMetric::defaultWeights(const RobotModel &robot)
    {
        Weights weights;
        bool baseOnly = robot.dof() > 0;
        for (unsigned int j = 0; j < robot.dof(); ++j)
            baseOnly = baseOnly && robot.isBaseJoint(j);
        if (baseOnly)
        {
            weights.toolWeight = 0.0;
            weights.rotationWeight = 0.0;
        }
        return weights;
    }

    void ManipulationMetric::planLegs(const MetricPoint &from, const MetricPoint &to, std::uint64_t moving,
                                      int first, LegPlan &plan) const
    {
        plan.legsAfter.resize(from.objects.size());
        plan.last.resize(from.objects.size());
        std::uint64_t pending = moving & ~(std::uint64_t{1} << first);
        double squared[MAX_OBJECTS];
        int last = first;
        double legs = 0.0;
        while (pending != 0)
        {
            // from where the tool left the last object to each pending one
            squaredDistances(pending, from.objects, to.objects[last], squared);
            double nearest = 0.0;
            last = nearestObject(pending, squared, &nearest);
            pending &= ~(std::uint64_t{1} << last);
            legs += approachCost(std::sqrt(nearest));
        }
        plan.legsAfter[first] = legs;
        plan.last[first] = last;
        plan.planned |= std::uint64_t{1} << first;
    }

    inline double ManipulationMetric::addToolLegs(const MetricPoint &from, const MetricPoint &to,
                                                  std::uint64_t moving, const double *startSquared,
                                                  const double *targetSquared, double cost, double cutoff,
                                                  LegPlan &plan) const
    {
        if (moving == 0)
            return cost;
        // the first object is the moving one nearest to the start; the rest of the visit is planned
        double nearest = 0.0;
        const int first = nearestObject(moving, startSquared, &nearest);
        cost += approachCost(std::sqrt(nearest));
        if (cost >= cutoff)
            return std::numeric_limits<double>::infinity();
        if ((moving & (moving - 1)) == 0)
            cost += std::sqrt(targetSquared[first]);
        else
        {
            if ((plan.planned >> first & 1) == 0)
                planLegs(from, to, moving, first, plan);
            cost += plan.legsAfter[first] + std::sqrt(targetSquared[plan.last[first]]);
        }
        return cost < cutoff ? cost : std::numeric_limits<double>::infinity();
    }

    double ManipulationMetric::legLowerBound(const Query &query, const ObjectCost &objectCost,
                                             const Eigen::AlignedBox3d &toolBox,
                                             const double *nearestSquared) const
    {
        if (objectCost.moving == 0)
            return 0.0;
        // as in nearest(): the tool meets the vertices' objects at the start (forward) or at the
        // end, and the sample's at the other end, from the sample's tool or, when its robot is
        // undefined, from the vertices' own (in the box)
        double first = std::numeric_limits<double>::infinity();
        double last = std::numeric_limits<double>::infinity();
        for (std::uint64_t rest = objectCost.moving; rest != 0; rest &= rest - 1)
        {
            const int i = __builtin_ctzll(rest);
            const double vertexSide = nearestSquared[i];
            const double sampleSide = query.robotDefined
                                          ? query.toolToObjects[i]
                                          : toolBox.squaredExteriorDistance(query.point.objects[i]);
            first = std::min(first, query.sampleIsTarget ? vertexSide : sampleSide);
            last = std::min(last, query.sampleIsTarget ? sampleSide : vertexSide);
        }
        return approachCost(std::sqrt(first)) + std::sqrt(last);
    }

    ManipulationMetric::ObjectCost ManipulationMetric::objectCost(const MetricPoint &objects,
                                                                  const Query &query) const
    {
        // raw arrays: a search calls this once per group and query
        const Eigen::Vector3d *positions = objects.objects.data();
        const Eigen::Vector3d *targets = query.point.objects.data();
        const double *yaws = objects.yaws.data();
        const double *targetYaws = query.point.yaws.data();
        ObjectCost cost;
        // objects that neither has displaced agree exactly
        for (std::uint64_t rest = query.definedObjects & (objects.displaced | query.point.displaced);
             rest != 0; rest &= rest - 1)
        {
            const int i = __builtin_ctzll(rest);
            const Eigen::Vector3d displacement = positions[i] - targets[i];
            if (displacement.cwiseAbs().maxCoeff() > SAME_COORDINATE ||
                std::abs(yaws[i] - targetYaws[i]) > SAME_COORDINATE)
            {
                cost.moving |= std::uint64_t{1} << i;
                cost.bound += weights_.movingObjectPenalty + displacement.norm();
            }
        }
        return cost;
    }

    double ManipulationMetric::distance(const MetricPoint &from, const MetricPoint &to) const
    {
        Query query;
        query.point = to;
        fillToolToObjects(query);
        query.definedObjects = allObjects(to.objects.size());
        return distance(from, query, objectCost(from, query));
    }

    void ManipulationMetric::makeQuery(const PartialState &sample, bool sampleIsTarget, Query &query) const
    {
        makePoint(sample.state(), query.point);
        fillToolToObjects(query);
        query.definedObjects = 0;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (sample.objectDefined(i))
                query.definedObjects |= std::uint64_t{1} << i;
        query.robotDefined = sample.robotDefined();
        query.sampleIsTarget = sampleIsTarget;
    }

    void ManipulationMetric::fillToolToObjects(Query &query) const
    {
        query.toolToObjects.resize(query.point.objects.size());
        squaredDistances(allObjects(query.point.objects.size()), query.point.objects, query.point.tool,
                         query.toolToObjects.data());
    }

    double ManipulationMetric::distance(const MetricPoint &vertex, const Query &query,
                                        const ObjectCost &objectCost, double cutoff) const
    {
        std::vector<double> packed(packedVertexSize());
        packVertex(vertex, vertex, packed.data());
        LegPlan plan;
        return distance(packed.data(), vertex, query, objectCost, cutoff, plan);
    }

    double ManipulationMetric::distance(const double *packedVertex, const MetricPoint &objects,
                                        const Query &query, const ObjectCost &objectCost, double cutoff,
                                        LegPlan &plan) const
    {
        double best = cutoff;
        return nearest(packedVertex, 1, objects, query, objectCost, plan, &best) == 0
                   ? best
                   : std::numeric_limits<double>::infinity();
    }

    int ManipulationMetric::nearest(const double *packedVertices, std::size_t count,
                                    const MetricPoint &objects, const Query &query,
                                    const ObjectCost &objectCost, LegPlan &plan, double *best) const
    {
        // the tool starts at the vertex (forward, or undefined robot) or at the sample, and ends at
        // the sample (forward with a defined robot) or at the vertex; an undefined robot takes the
        // vertex's pose, whose tool then meets the sample's objects
        const MetricPoint &from = query.sampleIsTarget ? objects : query.point;
        const MetricPoint &to = query.sampleIsTarget ? query.point : objects;
        const std::size_t stride = packedVertexSize();
        const std::size_t squaredOffset = 7 + query.point.joints.size();
        double crossSquared[MAX_OBJECTS];
        int nearest = -1;
        for (std::size_t k = 0; k < count; ++k)
        {
            const double *vertex = packedVertices + k * stride;
            double cost = objectCost.bound;
            if (query.robotDefined)
            {
                cost = robotTerm(vertex, query.point) + cost;
                if (cost >= *best)
                    continue;
            }
            const double *sampleSquared = query.toolToObjects.data();
            if (!query.robotDefined)
            {
                const Eigen::Vector3d vertexTool = Eigen::Map<const Eigen::Vector3d>(vertex);
                squaredDistances(objectCost.moving, query.point.objects, vertexTool, crossSquared);
                sampleSquared = crossSquared;
            }
            const double *vertexSquared = vertex + squaredOffset;
            cost = query.sampleIsTarget ? addToolLegs(from, to, objectCost.moving, vertexSquared,
                                                      sampleSquared, cost, *best, plan)
                                        : addToolLegs(from, to, objectCost.moving, sampleSquared,
                                                      vertexSquared, cost, *best, plan);
            if (cost < *best)
            {
                *best = cost;
                nearest = static_cast<int>(k);
            }
        }
        return nearest;
    }
}  // namespace ompl_mm
