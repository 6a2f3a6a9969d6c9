// Tests for ManipulationMetric.
#include "ompl_mm/base/ManipulationMetric.h"

#include "common/MobileArm.h"
#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

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

TEST_F(MobileMetric, ObjectCostSeesEveryObjectThatEitherSideDisplaced)
{
    // from_ and to_ start at the scene's start; obj1 moves by more than the tolerance (1e-9), obj2
    // by less, obj3 stands at the same place away from its start on both sides
    const ObjectPose obj1 = space_.objectPose(from_, 0);
    const ObjectPose obj2 = space_.objectPose(from_, 1);
    for (ob::State *displaced : {from_, to_})
    {
        space_.copyState(from_, to_);
        object(displaced, 0, V2(obj1.position.x() + 2e-9, obj1.position.y()));
        object(displaced, 1, V2(obj2.position.x(), obj2.position.y() + 5e-10));
        object(from_, 2, V2(0.3, 0.4));
        object(to_, 2, V2(0.3, 0.4));
        const ManipulationMetric::ObjectCost cost = queryFromTo();
        EXPECT_EQ(cost.moving, 1u) << (displaced == from_ ? "vertex" : "query") << " displaced";
        EXPECT_NEAR(cost.bound, MOVING + 2e-9, 1e-15);
        space_.copyState(from_, to_);
    }
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
    EXPECT_EQ(base.baseWeight, 1.0);
    EXPECT_EQ(base.toolWeight, 0.0);
    EXPECT_EQ(base.rotationWeight, 0.0);
}

TEST(ManipulationMetricWeights, EachJointCountsWithItsGroupsWeight)
{
    const ManipulationModelPtr model = mobileArm();
    const RobotModel &robot = model->robot();
    // the base's joints slide with nothing turning above them; the lift slides under the shoulder
    EXPECT_TRUE(robot.isBaseJoint(0));
    EXPECT_TRUE(robot.isBaseJoint(1));
    for (unsigned int j = 2; j < robot.dof(); ++j)
        EXPECT_FALSE(robot.isBaseJoint(j)) << robot.variableJoint(j).name;
    // a robot with an arm keeps the arm's weights
    const ManipulationMetric::Weights defaults = ManipulationMetric::defaultWeights(robot);
    EXPECT_EQ(defaults.toolWeight, 1.0);
    EXPECT_EQ(defaults.rotationWeight, 2.0);

    ManipulationStateSpace space(model);
    ManipulationMetric metric(&space);
    ManipulationMetric::Weights w = metric.weights();
    w.baseWeight = 2.0;
    w.jointWeight = 0.25;
    metric.setWeights(w);
    ob::State *a = space.allocState(), *b = space.allocState();
    const std::vector<double> qa{0.1, -0.2, 0.3, 0.1, -0.5}, qb{0.7, 0.2, -0.9, 0.4, 0.6};
    std::copy(qa.begin(), qa.end(), space.robotValues(a));
    std::copy(qb.begin(), qb.end(), space.robotValues(b));
    MetricPoint pa, pb;
    metric.makePoint(a, pa);
    metric.makePoint(b, pb);
    // written out: the base joints weighed by 2, the others by 0.25, the tool and its rotation from
    // forward kinematics
    double squared = 0.0;
    for (std::size_t j = 0; j < qa.size(); ++j)
        squared += std::pow((j < 2 ? 2.0 : 0.25) * (qa[j] - qb[j]), 2);
    const Eigen::Isometry3d ta = model->toolFrame(qa.data()), tb = model->toolFrame(qb.data());
    const double rotation =
        1.0 - std::abs(Eigen::Quaterniond(ta.linear()).dot(Eigen::Quaterniond(tb.linear())));
    EXPECT_NEAR(metric.distance(pa, pb),
                std::sqrt(squared) + (ta.translation() - tb.translation()).norm() + 2.0 * rotation, 1e-12);
    space.freeState(a);
    space.freeState(b);
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

TEST_F(MobileMetric, EqualNonZeroYawsDoNotCount)
{
    // every object turned, by the same yaw in both states: only obj2's displacement makes it move
    const double yaws[] = {0.7, -1.1, 2.5, -3.0};
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
    {
        const Eigen::Vector3d p = space_.objectPosition(from_, i);
        setObject(space_, from_, i, p.x(), p.y(), 0.0, yaws[i]);
        setObject(space_, to_, i, p.x(), p.y(), 0.0, yaws[i]);
    }
    const V2 r0(1.9, 1.9), r1(-0.3, 1.0), p0(0.8, -0.1), p1(0.2, 0.7);
    robot(to_, r1);
    setObject(space_, to_, 1, p1.x(), p1.y(), 0.0, yaws[1]);
    const double expected =
        (r1 - r0).norm() + MOVING + (p1 - p0).norm() + moveTo((p0 - r0).norm()) + (r1 - p1).norm();
    EXPECT_NEAR(distance(from_, to_), expected, 1e-12);
    // a yaw difference within 1e-9 is no turn either
    setObject(space_, to_, 3, 1.2, 1.9, 0.0, yaws[3] + 5e-10);
    EXPECT_NEAR(distance(from_, to_), expected, 1e-12);
}

TEST_F(MobileMetric, TurnedObjectIsVisitedLikeAMovedOne)
{
    // obj4 only turns (no displacement), obj2 is moved: both pay the penalty and are visited,
    // nearest to the tool first (obj4), then from obj4's target to obj2's start
    const V2 r0(1.9, 1.9), r1(1.0, 1.0), p0(0.8, -0.1), p1(0.2, 0.7), b0(1.2, 1.9);
    robot(to_, r1);
    object(to_, 1, p1);
    setObject(space_, to_, 3, b0.x(), b0.y(), 0.0, 1.2);
    const double expected = (r1 - r0).norm() + 2 * MOVING + (p1 - p0).norm() + moveTo((b0 - r0).norm()) +
                            moveTo((p0 - b0).norm()) + (r1 - p1).norm();
    EXPECT_NEAR(distance(from_, to_), expected, 1e-12);

    // turning obj4 alone: its penalty and the tool's way there and back
    space_.copyState(to_, from_);
    setObject(space_, to_, 3, b0.x(), b0.y(), 0.0, -2.0);
    EXPECT_NEAR(distance(from_, to_), MOVING + moveTo((b0 - r0).norm()) + (r0 - b0).norm(), 1e-12);
}

namespace
{
    using Weights = ManipulationMetric::Weights;

    /** The unit arm of test/data/unit_arm1.urdf (shoulder about world z at height 1, tool 0.5 m out
        along the arm) with one cup on a floor, and the metric with the default arm weights. */
    class ArmMetric : public ::testing::Test
    {
    protected:
        static Scene armScene()
        {
            Scene scene = unitArmScene();
            scene.surfaces.push_back(supportSurface("floor", V2(-1.0, -1.0), V2(1.0, 1.0)));
            scene.objects.push_back(cylinderObject("cup", 0.05, 0.1));
            return scene;
        }

        ~ArmMetric() override
        {
            space_.freeState(from_);
            space_.freeState(to_);
        }

        /** Sets the shoulder and the cup (on the floor) of s. */
        void set(ob::State *s, double q, const V2 &cup, double yaw)
        {
            space_.robotValues(s)[0] = q;
            setObject(space_, s, 0, cup.x(), cup.y(), 0.0, yaw);
        }

        double distance(const ob::State *a, const ob::State *b) const
        {
            MetricPoint pa, pb;
            metric_.makePoint(a, pa);
            metric_.makePoint(b, pb);
            return metric_.distance(pa, pb);
        }

        /** The tool point for shoulder angle q, written out. */
        static Eigen::Vector3d tool(double q) { return {0.5 * std::cos(q), 0.5 * std::sin(q), 1.0}; }

        /** The robot term written out: the tool turns about z by the shoulder angle, and the unit
            quaternions of turns by a and b about z have the dot product
            cos(a/2) cos(b/2) + sin(a/2) sin(b/2). */
        static double robotTerm(const Weights &w, double a, double b)
        {
            const double dot = std::cos(a / 2) * std::cos(b / 2) + std::sin(a / 2) * std::sin(b / 2);
            return w.robotWeight *
                   (w.jointWeight * std::abs(a - b) + w.toolWeight * (tool(a) - tool(b)).norm() +
                    w.rotationWeight * (1.0 - std::abs(dot)));
        }

        /** The tool's approach to an object d away. */
        static double approach(const Weights &w, double d)
        {
            return d > w.contactDistance ? w.moveToObjectPenalty + w.moveToObjectFactor * d : 0.0;
        }

        ManipulationStateSpace space_{makeModel(armScene())};
        ManipulationMetric metric_{&space_};
        ob::State *from_ = space_.allocState();
        ob::State *to_ = space_.allocState();
    };
}  // namespace

TEST_F(ArmMetric, RobotTermAddsToolDistanceAndRotationToTheJointDistance)
{
    // the default arm weights: 0.5 per radian, 1 per metre of the tool, 2 per unit of rotation
    const Weights w = metric_.weights();
    ASSERT_EQ(w.robotWeight, 1.0);
    ASSERT_EQ(w.jointWeight, 0.5);
    ASSERT_EQ(w.toolWeight, 1.0);
    ASSERT_EQ(w.rotationWeight, 2.0);
    const V2 cup(0.6, 0.2);
    for (const auto &[a, b] :
         std::vector<std::pair<double, double>>{{0.0, 1.0}, {0.3, -1.2}, {-3.0, 3.0}, {1.1, 1.1}})
    {
        set(from_, a, cup, 0.4);
        set(to_, b, cup, 0.4);
        const double expected = robotTerm(w, a, b);
        EXPECT_NEAR(distance(from_, to_), expected, 1e-12) << a << " -> " << b;
        EXPECT_NEAR(distance(to_, from_), expected, 1e-12) << b << " -> " << a;
        // the tool and rotation terms matter: the joint distance alone is well below
        if (a != b)
        {
            EXPECT_GT(expected - 0.5 * std::abs(a - b), 0.1) << a << " -> " << b;
        }
    }
}

TEST_F(ArmMetric, RotationTermTakesTheNearerOfTheTwoQuaternions)
{
    // turns by 2.9 and -2.9 are 0.48 rad apart although the joint moves 5.8 rad; without the
    // absolute value of the dot product the rotation term would be near 2 instead of near 0
    const Weights w = metric_.weights();
    set(from_, 2.9, V2(0.6, 0.2), 0.0);
    set(to_, -2.9, V2(0.6, 0.2), 0.0);
    const double rotation = 1.0 - std::abs(std::cos(2.9));
    EXPECT_LT(rotation, 0.05);
    EXPECT_NEAR(distance(from_, to_), 0.5 * 5.8 + 2.0 * 0.5 * std::sin(2.9) + 2.0 * rotation, 1e-12);
    EXPECT_NEAR(distance(from_, to_), robotTerm(w, 2.9, -2.9), 1e-12);
}

TEST_F(ArmMetric, RobotTermFollowsTheWeights)
{
    // weights apart from the defaults, so each term's factor is checked
    Weights w = metric_.weights();
    w.robotWeight = 2.0;
    w.jointWeight = 0.25;
    w.toolWeight = 3.0;
    w.rotationWeight = 0.5;
    metric_.setWeights(w);
    EXPECT_TRUE(metric_.boundUsesToolDistance());
    set(from_, 0.3, V2(0.6, 0.2), 0.4);
    set(to_, -1.2, V2(0.6, 0.2), 0.4);
    const double joint = 1.5, toolDistance = (tool(0.3) - tool(-1.2)).norm();
    const double rotation = 1.0 - std::cos(0.75);
    EXPECT_NEAR(distance(from_, to_), 2.0 * (0.25 * joint + 3.0 * toolDistance + 0.5 * rotation), 1e-12);

    // with the tool and rotation weights 0 the robot term is the weighted joint distance
    w.toolWeight = 0.0;
    w.rotationWeight = 0.0;
    metric_.setWeights(w);
    EXPECT_NEAR(distance(from_, to_), 2.0 * 0.25 * joint, 1e-12);
}

TEST_F(ArmMetric, MovedAndTurnedCupAddsPenaltyDisplacementAndToolLegsInSpace)
{
    // the tool is 1 m above the floor: its legs to and from the cup are 3-D distances
    const Weights w = metric_.weights();
    const double qa = 0.3, qb = -1.2;
    const Eigen::Vector3d c0(0.6, 0.2, 0.0), c1(0.2, 0.7, 0.0);
    set(from_, qa, c0.head<2>(), 0.4);
    set(to_, qb, c1.head<2>(), -0.5);
    const double expected = robotTerm(w, qa, qb) + w.movingObjectPenalty + (c1 - c0).norm() +
                            approach(w, (c0 - tool(qa)).norm()) + (tool(qb) - c1).norm();
    EXPECT_NEAR(distance(from_, to_), expected, 1e-12);

    // only turned (yaw 0.4 to -2.0): penalty and the tool's way to the cup and back, no displacement
    set(to_, qa, c0.head<2>(), -2.0);
    EXPECT_NEAR(distance(from_, to_),
                w.movingObjectPenalty + approach(w, (c0 - tool(qa)).norm()) + (tool(qa) - c0).norm(), 1e-12);
    // the same non-zero yaw at both ends: the robot term alone
    set(to_, qb, c0.head<2>(), 0.4);
    EXPECT_NEAR(distance(from_, to_), robotTerm(w, qa, qb), 1e-12);
}

TEST_F(ArmMetric, QueriesAgreeWithTheFullDistanceToTheCompletedSample)
{
    // random partial samples with random yaws: the prepared-query distance equals the full one,
    // and the robot lower bound (joint and tool distances) never exceeds it
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> joint(-3.0, 3.0), floor(-1.0, 1.0), yaw(-M_PI, M_PI);
    std::bernoulli_distribution coin(0.5);
    PartialState sample(&space_);
    ob::State *completed = space_.allocState();
    ManipulationMetric::Query query;
    MetricPoint vertex;
    for (int trial = 0; trial < 200; ++trial)
    {
        set(from_, joint(gen), V2(floor(gen), floor(gen)), yaw(gen));
        set(sample.state(), joint(gen), V2(floor(gen), floor(gen)), yaw(gen));
        if (coin(gen))
            space_.copyObject(sample.state(), from_, 0);
        sample.setRobotDefined(coin(gen));
        sample.setObjectDefined(0, coin(gen));
        const bool forward = coin(gen);
        metric_.makePoint(from_, vertex);
        metric_.makeQuery(sample, forward, query);
        const double d = metric_.distance(vertex, query, metric_.objectCost(vertex, query));
        sample.complete(from_, completed);
        EXPECT_NEAR(d, forward ? distance(from_, completed) : distance(completed, from_), 1e-9) << trial;
        // the bound takes the weighted joint distance, as the points hold the joints
        const double qv = space_.robotValues(from_)[0], qs = space_.robotValues(completed)[0];
        const double weighted = metric_.weights().jointWeight * std::abs(qv - qs);
        EXPECT_LE(metric_.robotLowerBound(query, weighted, (tool(qv) - tool(qs)).norm()), d + 1e-12) << trial;
    }
    space_.freeState(completed);
}
