// Tests for ManipulationMetric.
#include "ompl_mm/base/ManipulationMetric.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr double INF = std::numeric_limits<double>::infinity();
    // weights chosen apart from the defaults so that each term is visible
    constexpr double MOVING = 0.6, MOVE_TO = 0.25, FACTOR = 1.5, CONTACT = 0.08;

    using V2 = Eigen::Vector2d;

    class MobileMetric : public MobileBlockedTest
    {
    protected:
        MobileMetric()
        {
            ManipulationMetric::Weights weights = metric_.weights();
            weights.movingObjectPenalty = MOVING;
            weights.moveToObjectPenalty = MOVE_TO;
            weights.moveToObjectFactor = FACTOR;
            weights.contactDistance = CONTACT;
            metric_.setWeights(weights);
        }

        void robot(ob::State *s, const V2 &q) { setRobot(space_, s, q.x(), q.y()); }
        void object(ob::State *s, unsigned int i, const V2 &p) { setObject(space_, s, i, p.x(), p.y()); }
        double distance(const ob::State *a, const ob::State *b)
        {
            MetricPoint pa, pb;
            metric_.makePoint(a, pa);
            metric_.makePoint(b, pb);
            return metric_.distance(pa, pb);
        }
        /** Travel to an object at distance d (nothing within contact distance). */
        static double moveTo(double d) { return d > CONTACT ? MOVE_TO + FACTOR * d : 0.0; }

        /** Fills query_ (all of to_, as the target) and vertex_ (from_); returns their object cost. */
        ManipulationMetric::ObjectCost queryFromTo()
        {
            PartialState sample(&space_);
            space_.copyState(sample.state(), to_);
            metric_.makeQuery(sample, true, query_);
            metric_.makePoint(from_, vertex_);
            return metric_.objectCost(vertex_, query_);
        }

        ManipulationMetric metric_{&space_};
        ob::State *from_ = startCopy();
        ob::State *to_ = startCopy();
        ManipulationMetric::Query query_;
        MetricPoint vertex_;
    };
}  // namespace

TEST_F(MobileMetric, RobotOnlyIsJointDistance)
{
    robot(to_, V2(0.4, -0.2));
    EXPECT_NEAR(distance(from_, to_), std::hypot(1.9 - 0.4, 1.9 + 0.2), 1e-12);
    EXPECT_EQ(distance(from_, from_), 0.0);
}

TEST_F(MobileMetric, OneObjectAddsPenaltyDisplacementAndToolLegs)
{
    const V2 r0(1.9, 1.9), r1(-0.3, 1.0), p0(0.8, -0.1), p1(0.2, 0.7);
    robot(to_, r1);
    object(to_, 1, p1);
    // the tool is the disc's centre at floor height: the robot's joint values
    const double expected =
        (r1 - r0).norm() + MOVING + (p1 - p0).norm() + moveTo((p0 - r0).norm()) + (r1 - p1).norm();
    EXPECT_NEAR(distance(from_, to_), expected, 1e-12);

    // a tool already at the object does not pay the travel to it
    const V2 near = p0 + V2(0.05, 0.0);
    robot(from_, near);
    const double touching = (r1 - near).norm() + MOVING + (p1 - p0).norm() + 0.0 + (r1 - p1).norm();
    EXPECT_NEAR(distance(from_, to_), touching, 1e-12);
}

TEST_F(MobileMetric, ObjectsAreVisitedNearestFirst)
{
    // the tool starts next to obj4 (index 3), far from obj1 (index 0): nearest first visits obj4 first
    const V2 r0(1.0, 1.9), r1(0.0, 0.0);
    const V2 a0(-2.0, 0.3), a1(-2.0, 1.3);  // obj1
    const V2 b0(1.2, 1.9), b1(1.2, 1.0);    // obj4
    robot(from_, r0);
    robot(to_, r1);
    object(to_, 0, a1);
    object(to_, 3, b1);
    const double common = (r1 - r0).norm() + 2 * MOVING + (a1 - a0).norm() + (b1 - b0).norm();
    const double nearestFirst =
        common + moveTo((b0 - r0).norm()) + moveTo((a0 - b1).norm()) + (r1 - a1).norm();
    const double indexOrder = common + moveTo((a0 - r0).norm()) + moveTo((b0 - a1).norm()) + (r1 - b1).norm();
    ASSERT_GT(std::abs(nearestFirst - indexOrder), 0.1);
    EXPECT_NEAR(distance(from_, to_), nearestFirst, 1e-12);
}

TEST_F(MobileMetric, CutoffGivesInfinityAboveAndExactBelow)
{
    robot(to_, V2(-0.3, 1.0));
    object(to_, 1, V2(0.2, 0.7));
    object(to_, 2, V2(-0.9, -0.9));
    const double exact = distance(from_, to_);
    const ManipulationMetric::ObjectCost cost = queryFromTo();
    EXPECT_NEAR(metric_.distance(vertex_, query_, cost), exact, 1e-12);
    for (double cutoff : {exact + 1.0, exact + 1e-6, 2 * exact})
        EXPECT_NEAR(metric_.distance(vertex_, query_, cost, cutoff), exact, 1e-12) << cutoff;
    for (double cutoff : {0.0, 0.5, cost.bound, 0.5 * exact})
        EXPECT_EQ(metric_.distance(vertex_, query_, cost, cutoff), INF) << cutoff;
}

TEST_F(MobileMetric, CutoffJustBelowTheDistanceGivesInfinity)
{
    robot(to_, V2(-0.3, 1.0));
    object(to_, 1, V2(0.2, 0.7));
    const double exact = distance(from_, to_);
    const ManipulationMetric::ObjectCost cost = queryFromTo();
    EXPECT_EQ(metric_.distance(vertex_, query_, cost, exact - 1e-3), INF);
}

TEST_F(MobileMetric, UndefinedPartsOfAQueryDoNotCount)
{
    const V2 t(1.9, 1.9), p0(0.8, -0.1), p1(0.2, 0.7);
    PartialState sample(&space_);
    space_.copyState(sample.state(), from_);
    robot(sample.state(), V2(-2.0, -2.0));     // ignored: undefined
    object(sample.state(), 0, V2(2.0, -2.0));  // ignored: undefined
    object(sample.state(), 1, p1);             // obj2 must move
    sample.setRobotDefined(false);
    sample.setObjectDefined(0, false);
    ManipulationMetric::Query query;
    MetricPoint vertex;
    metric_.makePoint(from_, vertex);

    // forward tree: the vertex is `from`; the tool starts and ends at the vertex's tool
    metric_.makeQuery(sample, true, query);
    ManipulationMetric::ObjectCost cost = metric_.objectCost(vertex, query);
    EXPECT_EQ(cost.moving, std::uint64_t{1} << 1);
    EXPECT_NEAR(cost.bound, MOVING + (p1 - p0).norm(), 1e-12);
    const double forward = MOVING + (p1 - p0).norm() + moveTo((p0 - t).norm()) + (t - p1).norm();
    EXPECT_NEAR(metric_.distance(vertex, query, cost), forward, 1e-12);

    // backward tree: the sample is `from`; obj2 goes from p1 back to p0
    metric_.makeQuery(sample, false, query);
    cost = metric_.objectCost(vertex, query);
    const double backward = MOVING + (p1 - p0).norm() + moveTo((p1 - t).norm()) + (t - p0).norm();
    EXPECT_NEAR(metric_.distance(vertex, query, cost), backward, 1e-12);

    // with the robot defined, the robot term and the tool legs use the sample's robot
    const V2 q(-1.0, 1.5);
    robot(sample.state(), q);
    sample.setRobotDefined(true);
    metric_.makeQuery(sample, false, query);
    cost = metric_.objectCost(vertex, query);
    const double withRobot =
        (q - t).norm() + MOVING + (p1 - p0).norm() + moveTo((p1 - q).norm()) + (t - p0).norm();
    EXPECT_NEAR(metric_.distance(vertex, query, cost), withRobot, 1e-12);
}

TEST_F(MobileMetric, ObjectCostBoundsTheDistance)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> floor(-2.5, 2.5);
    std::bernoulli_distribution coin(0.5);
    PartialState sample(&space_);
    ob::State *vertexState = space_.allocState();
    ManipulationMetric::Query query;
    MetricPoint vertex;
    for (int trial = 0; trial < 200; ++trial)
    {
        space_.copyState(vertexState, from_);
        space_.copyState(sample.state(), from_);
        robot(vertexState, V2(floor(gen), floor(gen)));
        robot(sample.state(), V2(floor(gen), floor(gen)));
        sample.setRobotDefined(coin(gen));
        for (unsigned int i = 0; i < space_.objectCount(); ++i)
        {
            object(vertexState, i, V2(floor(gen), floor(gen)));
            if (coin(gen))
                object(sample.state(), i, V2(floor(gen), floor(gen)));
            else
                space_.copyObject(sample.state(), vertexState, i);
            sample.setObjectDefined(i, coin(gen));
        }
        const bool forward = coin(gen);
        metric_.makePoint(vertexState, vertex);
        metric_.makeQuery(sample, forward, query);
        const ManipulationMetric::ObjectCost cost = metric_.objectCost(vertex, query);
        const double d = metric_.distance(vertex, query, cost);
        EXPECT_LE(cost.bound, d + 1e-12) << trial;

        // the query distance equals the full distance to the sample completed by the vertex
        ob::State *completed = space_.allocState();
        sample.complete(vertexState, completed);
        const double full = forward ? distance(vertexState, completed) : distance(completed, vertexState);
        EXPECT_NEAR(d, full, 1e-9) << trial;
        space_.freeState(completed);
    }
    space_.freeState(vertexState);
}

TEST(ManipulationMetricWeights, DefaultsFollowTheRobotsJoints)
{
    const ManipulationMetric::Weights arm =
        ManipulationMetric::defaultWeights(makeModel(unitArmScene())->robot());
    EXPECT_EQ(arm.jointWeight, 0.5);
    EXPECT_EQ(arm.toolWeight, 1.0);
    EXPECT_EQ(arm.rotationWeight, 2.0);
    const ManipulationMetric::Weights base =
        ManipulationMetric::defaultWeights(makeModel(mobileBlockedScene())->robot());
    EXPECT_EQ(base.jointWeight, 1.0);
    EXPECT_EQ(base.toolWeight, 0.0);
    EXPECT_EQ(base.rotationWeight, 0.0);
}

TEST_F(MobileMetric, ToolWeightAddsTheToolDistanceToTheRobotTerm)
{
    robot(to_, V2(0.4, -0.2));
    const double joints = std::hypot(1.9 - 0.4, 1.9 + 0.2);
    ManipulationMetric::Weights weights = metric_.weights();
    weights.toolWeight = 0.5;
    weights.robotWeight = 2.0;
    metric_.setWeights(weights);
    // the tool moves with the base: its distance equals the joint distance
    EXPECT_NEAR(distance(from_, to_), 2.0 * (joints + 0.5 * joints), 1e-12);
}
