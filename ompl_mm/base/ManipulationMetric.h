#pragma once

#include "ompl_mm/base/PartialState.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <vector>

namespace ompl_mm
{
    /** What the metric needs of a configuration, computed once per tree vertex (forward
        kinematics is the expensive part). */
    struct MetricPoint
    {
        std::vector<double> joints;  ///< each times its group's weight (Weights), metres or radians
        Eigen::Vector3d tool{Eigen::Vector3d::Zero()};                    ///< tool point in the world, metres
        Eigen::Quaterniond toolRotation{Eigen::Quaterniond::Identity()};  ///< tool frame's world rotation
        std::vector<Eigen::Vector3d> objects;  ///< base centres in the world, metres
        std::vector<double> yaws;              ///< object rotations about world z, radians
        /** Bit i: object i stands elsewhere than its start pose in the scene (any difference), so
            two points whose bit i is clear agree on object i: the object terms need only look at
            the objects either has displaced. */
        std::uint64_t displaced{0};
    };

    /** MOPL's distance ("mini empty-space planner with penalties"): an estimate of how far the
        robot must travel to turn one configuration into another. It adds to the robot's own
        distance, for every object that must move, a penalty and the object's displacement, plus
        the legs the tool travels to reach each object (visited greedily, nearest first) and back
        to its target. Rickert, Sieverling, Brock, "Balancing exploration and exploitation in
        sampling-based motion planning", IEEE T-RO 2014 / Jentzsch et al., MOPL (IROS 2015),
        section III-B.3. Directed: d(a, b) is the cost of going from a to b. Keeps a pointer to its
        space, which must outlive it. */
    class ManipulationMetric
    {
    public:
        /** Weights of the metric; defaults are the paper's values for arms. The robot term is
            robotWeight * (|W (q_a - q_b)| + toolWeight * tool distance + rotationWeight * (1 -
            |r_a . r_b|) of the tool rotations r), where the diagonal W weighs each joint by its
            group: baseWeight for a mobile base's joints (RobotModel::isBaseJoint), jointWeight for
            the others (an arm's, a torso's). */
        struct Weights
        {
            double robotWeight{1.0};          ///< factor on the whole robot term
            double jointWeight{0.5};          ///< on the joints that are no base joints (radians or metres)
            double baseWeight{1.0};           ///< on a mobile base's joints (metres)
            double toolWeight{1.0};           ///< on the tool point's distance, per metre
            double rotationWeight{2.0};       ///< on the tool's rotation distance (0 to 1)
            double movingObjectPenalty{0.1};  ///< added per object that moves, metres
            double moveToObjectPenalty{0.3};  ///< added when the tool must travel to an object, metres
            double moveToObjectFactor{1.0};   ///< factor on that travel distance
            double contactDistance{0.08};  ///< closer than this, no travel to the object is counted, metres
        };

        /** Weights for a robot: the paper's for arms; for a robot that is a mobile base alone
            (every joint a base joint) the joints are the tool's position, so its robot term is the
            joint distance alone (toolWeight and rotationWeight 0), as in the paper's mobile scene. */
        static Weights defaultWeights(const RobotModel &robot);

        /** Starts with defaultWeights() of the space's robot.
            @throws ompl::Exception when the space has more than MAX_OBJECTS objects. */
        explicit ManipulationMetric(const ManipulationStateSpace *space);

        /** Sets the weights; they count for points made from now on (makePoint(), makeQuery()),
            so a planner sets them before it builds its trees. */
        void setWeights(const Weights &weights);
        /** The weights in use. */
        const Weights &weights() const { return weights_; }

        /** Computes the cached quantities of a fully defined state. */
        void makePoint(const ompl::base::State *state, MetricPoint &point) const;

        /** Distance from `from` to `to`, both fully defined. */
        double distance(const MetricPoint &from, const MetricPoint &to) const;

        /** A partial sample prepared for many distance evaluations against tree vertices: its
            undefined parts take each vertex's values. */
        struct Query
        {
            MetricPoint point;                  ///< the sample's quantities (undefined parts hold anything)
            std::vector<double> toolToObjects;  ///< squared distances from point.tool to point.objects
            std::uint64_t definedObjects{0};    ///< bit i: the sample defines object i
            bool robotDefined{true};            ///< the sample defines the robot's joints
            bool sampleIsTarget{true};  ///< the sample is `to` (forward tree) or `from` (backward tree)
        };

        /** Fills query from a partial sample; sampleIsTarget says whether the sample is `to`
            (forward tree) or `from` (backward tree) of the distances. */
        void makeQuery(const PartialState &sample, bool sampleIsTarget, Query &query) const;

        /** What all vertices with the same objects share in their distance to a query: which
            objects must move, and the penalties and displacements that costs (a lower bound). */
        struct ObjectCost
        {
            std::uint64_t moving{0};  ///< bit i: object i must move
            double bound{0.0};        ///< sum of the moving objects' penalties and displacements, metres
        };
        /** The ObjectCost of vertices whose objects are those of `objects` against query: an object
            must move when the query defines it and its pose differs (beyond 1e-9). Looks only at
            the objects that one of them has displaced (MetricPoint::displaced). */
        ObjectCost objectCost(const MetricPoint &objects, const Query &query) const;

        /** A lower bound of the robot term for robots whose weighted joints (MetricPoint::joints)
            lie at least jointDistance and whose tool lies at least toolDistance from the query's (0
            when its robot is undefined). */
        double robotLowerBound(const Query &query, double jointDistance, double toolDistance) const
        {
            if (!query.robotDefined)
                return 0.0;
            if (jointDistanceOnly_)
                return jointDistance;
            return weights_.robotWeight * (jointDistance + weights_.toolWeight * toolDistance);
        }
        /** False when robotLowerBound() ignores the tool distance (the plain joint distance), so callers may
            skip computing it. */
        bool boundUsesToolDistance() const { return !jointDistanceOnly_; }

        /** A lower bound of the tool's legs (first approach and final return) for vertices with
            the same objects whose tool points lie in toolBox and whose squared tool distance to
            object i is at least nearestSquared[i]. */
        double legLowerBound(const Query &query, const ObjectCost &objectCost,
                             const Eigen::AlignedBox3d &toolBox, const double *nearestSquared) const;

        /** Distance between a tree vertex and a prepared sample; returns infinity as soon as the
            distance is known to reach `cutoff` (exact below it), which makes linear scans fast.
            objectCost must be objectCost(vertex, query) or that of a vertex with the same objects. */
        double distance(const MetricPoint &vertex, const Query &query, const ObjectCost &objectCost,
                        double cutoff = std::numeric_limits<double>::infinity()) const;

        /** Doubles in a packed vertex: tool point (3), tool rotation (4: x y z w), joints, then the
            squared distance from the tool to each object. */
        std::size_t packedVertexSize() const { return 7 + space_->robotDimension() + space_->objectCount(); }
        /** Writes the robot part of point and its tool's squared distances to the objects of
            `objects`, packed, to out (packedVertexSize() doubles): trees keep these contiguous, so a
            scan touches little memory and needs no object geometry of its own. */
        void packVertex(const MetricPoint &point, const MetricPoint &objects, double *out) const;
        /** The tool's squared distances to the objects in a packed vertex. */
        const double *packedToolToObjects(const double *packedVertex) const
        {
            return packedVertex + 7 + space_->robotDimension();
        }
        /** The greedy visit of the moving objects depends on a vertex only through its first
            object (the one nearest to its tool); per object i visited first: the cost of the legs
            after it and the object visited last. Shared by vertices with the same objects; each
            visit is planned on first use. */
        struct LegPlan
        {
            std::uint64_t planned{0};       ///< bit i: the visit starting at object i is planned
            std::vector<double> legsAfter;  ///< per first object i: cost of the legs after it
            std::vector<int> last;          ///< per first object i: the object visited last
        };

        /** As distance() for a vertex packed (packVertex) with `objects`; plan (planned = 0 for
            each query and object configuration) saves work across such vertices. */
        double distance(const double *packedVertex, const MetricPoint &objects, const Query &query,
                        const ObjectCost &objectCost, double cutoff, LegPlan &plan) const;
        /** Scans `count` vertices with the same objects, packed one after the other: the position
            of the first one nearest to the query and nearer than *best (whose distance then goes
            to *best), -1 when there is none. One call per group keeps the scan's loop tight. */
        int nearest(const double *packedVertices, std::size_t count, const MetricPoint &objects,
                    const Query &query, const ObjectCost &objectCost, LegPlan &plan, double *best) const;

    private:
        /** Cost of the tool's approach to the first object, `distance` away. */
        double approachCost(double distance) const
        {
            return distance > weights_.contactDistance
                       ? weights_.moveToObjectPenalty + weights_.moveToObjectFactor * distance
                       : 0.0;
        }
        /** Fills query.toolToObjects from query.point. */
        void fillToolToObjects(Query &query) const;
        /** The robot's own distance between a packed vertex and a point (symmetric). */
        double robotTerm(const double *packedVertex, const MetricPoint &point) const;
        /** Adds to `cost` the tool's legs from its start to each moving object of `from` (nearest
            first) and on to its target, given the squared distances from the start to the objects
            of `from` and from the target to those of `to`; infinity once the total reaches cutoff. */
        double addToolLegs(const MetricPoint &from, const MetricPoint &to, std::uint64_t moving,
                           const double *startSquared, const double *targetSquared, double cost,
                           double cutoff, LegPlan &plan) const;
        /** Plans the visit of the objects moving from `from` to `to` that starts at object first. */
        void planLegs(const MetricPoint &from, const MetricPoint &to, std::uint64_t moving, int first,
                      LegPlan &plan) const;

        const ManipulationStateSpace *space_;
        Weights weights_;
        /** Per joint, the weight of its group (Weights). */
        std::vector<double> jointScales_;
        /** The robot term is the weighted joint distance alone (tool and rotation weights 0,
            robotWeight 1): the hot loops then skip the tool's terms. */
        bool jointDistanceOnly_{false};
    };
}  // namespace ompl_mm
