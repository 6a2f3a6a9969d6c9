#pragma once

#include "ompl_mm/base/ManipulationMetric.h"
#include "ompl_mm/primitives/Trajectory.h"

#include <limits>
#include <vector>

namespace ompl_mm
{
    /** One search tree of MOPL: vertices with their parent, the label of the edge to the parent
        and the cached metric quantities. Nearest-neighbour search is exact for the directed
        manipulation metric, which no metric tree can index: vertices are grouped by object
        configuration (a vertex reached by a transit joins its parent's group); a group is skipped
        whole when a lower bound of its distance (its objects' cost, the robot's distance to the
        group's bounding boxes of joints and tool points, and the tool's shortest approach and
        return) reaches the best distance so far, and the rest are scanned with early termination.
        Owns its states. forward: edges lead away from the roots (start tree); backward: edges lead
        towards the roots (goal tree), and a vertex's label is that of the edge to its parent. */
    class ManipulationTree
    {
    public:
        /** One vertex of the tree. */
        struct Vertex
        {
            ompl::base::State *state;  ///< owned by the tree
            int parent;                ///< -1 for a root
            SegmentLabel label;        ///< of the edge between parent and this vertex
            std::size_t group;         ///< index of its object configuration, NO_GROUP when not branchable
        };
        /** The group of a vertex that nearest() never returns. */
        static constexpr std::size_t NO_GROUP = static_cast<std::size_t>(-1);

        /** An empty tree. @pre space and metric outlive it. */
        ManipulationTree(const ManipulationStateSpace *space, const ManipulationMetric *metric, bool forward);
        /** Frees the states. */
        ~ManipulationTree();
        ManipulationTree(const ManipulationTree &) = delete;             ///< not copyable
        ManipulationTree &operator=(const ManipulationTree &) = delete;  ///< not copyable

        /** True for a start tree, false for a goal tree. */
        bool forward() const { return forward_; }
        /** Number of vertices. */
        std::size_t size() const { return vertices_.size(); }
        /** True when the tree has no vertex. */
        bool empty() const { return vertices_.empty(); }
        /** Vertex i, in the order added. */
        const Vertex &vertex(std::size_t i) const { return vertices_[i]; }
        /** Number of roots (vertices without parent). */
        std::size_t rootCount() const { return roots_; }

        /** Adds a copy of state with parent (-1 for a new root) and the label of the edge between
            them; returns its index. A vertex that is not branchable (Trajectory::branchable) stays
            on its branch but nearest() never returns it. */
        int add(const ompl::base::State *state, int parent, SegmentLabel label, bool branchable = true);
        /** Removes the most recently added vertex. @pre it has no children. */
        void removeLast();
        /** Removes all vertices. */
        void clear();

        /** Index of the vertex nearest to the prepared sample (made for this tree's direction),
            and its distance in *distance; only vertices closer than cutoff count, -1 when there
            is none (or the tree is empty). */
        int nearest(const ManipulationMetric::Query &query, double *distance,
                    double cutoff = std::numeric_limits<double>::infinity()) const;

        /** Indices from a root to vertex i (forward tree) or from vertex i to its root (backward). */
        std::vector<int> branch(int i) const;

    private:
        const ManipulationStateSpace *space_;
        const ManipulationMetric *metric_;
        bool forward_;
        /** Bounds of a group's members: boxes around their joints and tool points and their
            tools' least squared distance to each object of the group; an offset into boxes_,
            where joint lows, joint highs, tool lows (3), tool highs (3) and those distances
            follow each other. */
        using Bounds = std::size_t;
        Bounds newBounds();
        /** Extends bounds by a vertex with its packed data (ManipulationMetric::packVertex). */
        void extendBounds(Bounds bounds, const MetricPoint &point, const double *packed);

        /** Vertices sharing one object configuration: the metric's quantities of their robots
            are packed, those of their objects kept once. */
        struct Group
        {
            MetricPoint objects;  ///< the metric's quantities of its first member
            std::vector<int> members;
            std::vector<double> packed;  ///< ManipulationMetric::packVertex of the members, in order
            Bounds bounds;
        };

        /** Lower bound of the distance from the members of group g to the query: the objects'
            cost and the robot's distance to the boxes. */
        double objectAndRobotBound(std::size_t g, const ManipulationMetric::Query &query) const;
        /** Lower bound of the tool's first approach and last return for those vertices. */
        double legBound(std::size_t g, const ManipulationMetric::Query &query) const;
        /** True unless the bounds show that no member of group g is nearer than best. */
        bool mayBeat(std::size_t g, const ManipulationMetric::Query &query, double best) const;
        /** Scans the members of group g for one nearer than *bestDistance. */
        void scanGroup(std::size_t g, const ManipulationMetric::Query &query, int *best,
                       double *bestDistance) const;

        std::vector<Vertex> vertices_;
        std::vector<Group> groups_;
        std::vector<double> boxes_;  ///< storage of all Bounds
        mutable std::vector<ManipulationMetric::ObjectCost> groupCosts_;
        mutable std::vector<double> groupBounds_;
        mutable ManipulationMetric::LegPlan legPlan_;  ///< of the group being scanned
        MetricPoint point_;                            ///< of the vertex being added
        std::size_t roots_{0};
    };
}  // namespace ompl_mm
