// Tests for ManipulationTree.
#include "ompl_mm/planners/ManipulationTree.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr double INF = std::numeric_limits<double>::infinity();

    class MobileTree : public MobileBlockedTest
    {
    protected:
        MobileTree()
        {
            ManipulationMetric::Weights weights = metric_.weights();
            weights.movingObjectPenalty = 0.6;
            weights.moveToObjectPenalty = 0.1;
            weights.moveToObjectFactor = 1.0;
            metric_.setWeights(weights);
        }

        double uniform() { return position_(gen_); }

        /** Adds n random vertices: new roots, transits (robot moves) and pushes (one object moves). */
        void grow(ManipulationTree &tree, int n)
        {
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            for (int k = 0; k < n; ++k)
            {
                const double kind = unit(gen_);
                if (tree.empty() || kind < 0.05)
                {
                    space_.copyState(scratch_, start_);
                    randomRobot(scratch_);
                    tree.add(scratch_, -1, {});
                    continue;
                }
                const int parent =
                    std::uniform_int_distribution<int>(0, static_cast<int>(tree.size()) - 1)(gen_);
                space_.copyState(scratch_, tree.vertex(parent).state);
                randomRobot(scratch_);
                SegmentLabel label;
                if (kind < 0.5)
                {
                    const int object = std::uniform_int_distribution<int>(0, 3)(gen_);
                    randomObject(scratch_, object);
                    label = {PrimitiveKind::Push, object};
                }
                tree.add(scratch_, parent, label);
            }
        }
        void randomRobot(ob::State *s)
        {
            space_.robotValues(s)[0] = uniform();
            space_.robotValues(s)[1] = uniform();
        }
        void randomObject(ob::State *s, unsigned int i)
        {
            space_.setObjectPose(s, i, {Eigen::Vector3d(uniform(), uniform(), 0.0), 0.0});
        }

        /** A random partial sample; defined objects sometimes keep the start pose. */
        void randomSample(PartialState &sample)
        {
            std::bernoulli_distribution coin(0.5);
            space_.copyState(sample.state(), start_);
            randomRobot(sample.state());
            sample.setRobotDefined(coin(gen_));
            for (unsigned int i = 0; i < space_.objectCount(); ++i)
            {
                if (coin(gen_))
                    randomObject(sample.state(), i);
                sample.setObjectDefined(i, coin(gen_));
            }
        }

        /** Smallest distance by brute force: the full metric to the sample completed by each vertex. */
        double bruteForce(const ManipulationTree &tree, const PartialState &sample)
        {
            double best = INF;
            MetricPoint vertex, completed;
            for (std::size_t v = 0; v < tree.size(); ++v)
            {
                sample.complete(tree.vertex(v).state, scratch_);
                metric_.makePoint(tree.vertex(v).state, vertex);
                metric_.makePoint(scratch_, completed);
                best = std::min(best, tree.forward() ? metric_.distance(vertex, completed)
                                                     : metric_.distance(completed, vertex));
            }
            return best;
        }

        void expectExactNearest(const ManipulationTree &tree, int queries)
        {
            PartialState sample(&space_);
            ManipulationMetric::Query query;
            for (int k = 0; k < queries; ++k)
            {
                randomSample(sample);
                metric_.makeQuery(sample, tree.forward(), query);
                double d = -1.0;
                const int nearest = tree.nearest(query, &d);
                ASSERT_GE(nearest, 0);
                EXPECT_NEAR(d, bruteForce(tree, sample), 1e-9) << "query " << k;
                // the reported distance is that of the returned vertex
                MetricPoint point;
                metric_.makePoint(tree.vertex(nearest).state, point);
                EXPECT_NEAR(metric_.distance(point, query, metric_.objectCost(point, query)), d, 1e-9)
                    << "query " << k;
            }
        }

        ManipulationMetric metric_{&space_};
        ob::State *start_ = startCopy();
        ob::State *scratch_ = newState();
        std::mt19937 gen_{11};
        std::uniform_real_distribution<double> position_{-2.5, 2.5};
    };
}  // namespace

TEST_F(MobileTree, EmptyTreeHasNoNearest)
{
    ManipulationTree tree(&space_, &metric_, true);
    EXPECT_TRUE(tree.empty());
    PartialState sample(&space_);
    ManipulationMetric::Query query;
    metric_.makeQuery(sample, true, query);
    double d = 0.0;
    EXPECT_EQ(tree.nearest(query, &d), -1);
    EXPECT_EQ(d, INF);
}

TEST_F(MobileTree, NearestIsExactForTheForwardTree)
{
    ManipulationTree tree(&space_, &metric_, true);
    grow(tree, 300);
    ASSERT_EQ(tree.size(), 300u);
    expectExactNearest(tree, 300);
}

TEST_F(MobileTree, NearestIsExactForTheBackwardTree)
{
    ManipulationTree tree(&space_, &metric_, false);
    grow(tree, 300);
    expectExactNearest(tree, 300);
}

TEST_F(MobileTree, NearestFindsAVertexJustBelowTheCutoff)
{
    // the search's bounds round differently from the distances; they must not prune a vertex
    // whose distance lies just below the cutoff
    PartialState sample(&space_);
    ManipulationMetric::Query query;
    for (bool forward : {true, false})
        for (int k = 0; k < 400; ++k)
        {
            ManipulationTree tree(&space_, &metric_, forward);
            grow(tree, 3);
            randomSample(sample);
            metric_.makeQuery(sample, forward, query);
            double exact = INF;
            for (std::size_t v = 0; v < tree.size(); ++v)
            {
                MetricPoint point;
                metric_.makePoint(tree.vertex(v).state, point);
                exact = std::min(exact, metric_.distance(point, query, metric_.objectCost(point, query)));
            }
            double d = -1.0;
            EXPECT_GE(tree.nearest(query, &d, std::nextafter(exact, INF)), 0) << forward << " " << k;
            EXPECT_EQ(d, exact) << forward << " " << k;
        }
}

TEST_F(MobileTree, AddCopiesTheState)
{
    ManipulationTree tree(&space_, &metric_, true);
    const int root = tree.add(start_, -1, {});
    EXPECT_EQ(root, 0);
    const ManipulationTree::Vertex &v = tree.vertex(0);
    EXPECT_NE(v.state, start_);
    EXPECT_TRUE(space_.equalStates(v.state, start_));
    EXPECT_EQ(v.parent, -1);
}

TEST_F(MobileTree, RemoveLastRestoresSizeAndRoots)
{
    ManipulationTree tree(&space_, &metric_, true);
    grow(tree, 40);
    const std::size_t size = tree.size();
    const std::size_t roots = tree.rootCount();
    space_.copyState(scratch_, start_);
    tree.add(scratch_, -1, {});
    EXPECT_EQ(tree.rootCount(), roots + 1);
    randomObject(scratch_, 1);
    tree.add(scratch_, static_cast<int>(size), {PrimitiveKind::Push, 1});
    randomRobot(scratch_);
    tree.add(scratch_, static_cast<int>(size) + 1, {});
    EXPECT_EQ(tree.size(), size + 3);
    tree.removeLast();
    tree.removeLast();
    EXPECT_EQ(tree.rootCount(), roots + 1);
    tree.removeLast();
    EXPECT_EQ(tree.size(), size);
    EXPECT_EQ(tree.rootCount(), roots);
    // the search structure stays consistent
    expectExactNearest(tree, 50);
    tree.clear();
    EXPECT_TRUE(tree.empty());
    EXPECT_EQ(tree.rootCount(), 0u);
}

TEST_F(MobileTree, BranchOrderFollowsTheTreeDirection)
{
    for (bool forward : {true, false})
    {
        ManipulationTree tree(&space_, &metric_, forward);
        space_.copyState(scratch_, start_);
        tree.add(scratch_, -1, {});  // 0
        randomRobot(scratch_);
        tree.add(scratch_, 0, {});  // 1
        randomRobot(scratch_);
        tree.add(scratch_, 0, {});  // 2
        randomObject(scratch_, 0);
        tree.add(scratch_, 1, {PrimitiveKind::Push, 0});  // 3
        randomRobot(scratch_);
        tree.add(scratch_, 3, {});  // 4
        const std::vector<int> expected =
            forward ? std::vector<int>{0, 1, 3, 4} : std::vector<int>{4, 3, 1, 0};
        EXPECT_EQ(tree.branch(4), expected) << forward;
        EXPECT_EQ(tree.branch(0), std::vector<int>{0});
        EXPECT_EQ(tree.branch(2), forward ? (std::vector<int>{0, 2}) : (std::vector<int>{2, 0}));
        EXPECT_EQ(tree.vertex(3).label, (SegmentLabel{PrimitiveKind::Push, 0}));
        EXPECT_EQ(tree.vertex(3).parent, 1);
        EXPECT_EQ(tree.forward(), forward);
    }
}
