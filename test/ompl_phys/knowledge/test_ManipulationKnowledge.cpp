// Tests for ManipulationKnowledge: the contact and state rules on hand-made states (fixed, free and
// constraint-oriented bodies, regions, speeds), the goal's occupants and moving them off the goal.
#include "ompl_phys/knowledge/ManipulationKnowledge.h"

#include "ompl_phys/common/PhysicsTestSupport.h"
#include "ompl_phys/world/PhysicsWorld.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    const double PI = std::acos(-1.0);

    /** Start states of a scene (PhysicsWorld's numbering), built without a world. */
    BodyStates startStatesOf(const PhysicsScene &scene)
    {
        BodyStates states(1);
        states[0].position = scene.robot.start;
        for (std::size_t body : scene.movableBodies())
        {
            states.emplace_back();
            states.back().position = scene.bodies[body].start.translation();
            states.back().orientation = Eigen::Quaterniond(scene.bodies[body].start.linear());
        }
        return states;
    }

    /** The moving index (>= 1) of the scene body with this name. */
    std::size_t movingIndex(const PhysicsScene &scene, const std::string &name)
    {
        const std::vector<std::size_t> movable = scene.movableBodies();
        const std::size_t body = scene.bodyIndex(name);
        for (std::size_t i = 0; i < movable.size(); ++i)
            if (movable[i] == body)
                return i + 1;
        return 0;
    }

    /** Whether a robot standing anywhere on the goal disc would overlap the footprint of body in state s,
        by sampling the disc densely (an independent check of goalOccupants: a different algorithm). */
    bool robotOnGoalWouldOverlap(const PhysicsScene &scene, std::size_t body, const BodyState &s)
    {
        const PhysicsShape &shape = scene.bodies[body].shape;
        for (int ring = 0; ring <= 40; ++ring)
            for (int k = 0; k < 360; ++k)
            {
                const double radius = scene.goal.radius * ring / 40.0;
                const double angle = 2.0 * PI * k / 360.0;
                const Eigen::Vector2d at =
                    scene.goal.centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
                if (footprintDistance(shape, s.position.head<2>(), yawOf(s.orientation), at) <
                    scene.robot.radius)
                    return true;
            }
        return false;
    }

    /** The small scene and its knowledge; slider (constrained, push axis = world y) is moving body 2. */
    class SmallSceneKnowledge : public ::testing::Test
    {
    protected:
        SmallSceneKnowledge()
            : scene_(smallScene()), knowledge_(shared(scene_)), start_(startStatesOf(scene_))
        {
        }

        const PhysicsScene scene_;
        const ManipulationKnowledge knowledge_;
        const BodyStates start_;
        const std::size_t wall_{scene_.bodyIndex("wall")};
        const std::size_t wedge_{scene_.bodyIndex("wedge")};
        const std::size_t loose_{scene_.bodyIndex("loose")};
        const std::size_t slider_{scene_.bodyIndex("slider")};
        const std::size_t looseMoving_{movingIndex(scene_, "loose")};
        const std::size_t sliderMoving_{movingIndex(scene_, "slider")};
    };
}  // namespace

TEST_F(SmallSceneKnowledge, StartIsAcceptable)
{
    ASSERT_EQ(looseMoving_, 1u);
    ASSERT_EQ(sliderMoving_, 2u);
    EXPECT_EQ(knowledge_.checkStates(start_), Violation::None);
    EXPECT_EQ(knowledge_.checkTouches({}, start_), Violation::None);
}

TEST_F(SmallSceneKnowledge, FixedBodiesMayNeverBeTouched)
{
    EXPECT_FALSE(knowledge_.touchAllowed(wall_, start_[0].position, BodyState()));
    EXPECT_FALSE(knowledge_.touchAllowed(wedge_, start_[0].position, BodyState()));
    EXPECT_EQ(knowledge_.checkTouches({wall_}, start_), Violation::TouchedFixedBody);
    EXPECT_EQ(knowledge_.checkTouches({loose_, wedge_}, start_), Violation::TouchedFixedBody);
}

TEST_F(SmallSceneKnowledge, FreeBodiesMayBeTouchedAnywhere)
{
    const BodyState &loose = start_[looseMoving_];
    for (int k = 0; k < 16; ++k)
    {
        const double angle = 2.0 * PI * k / 16.0;
        const Eigen::Vector3d robot =
            loose.position + 0.18 * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
        EXPECT_TRUE(knowledge_.touchAllowed(loose_, robot, loose)) << angle;
        BodyStates states = start_;
        states[0].position = robot;
        EXPECT_EQ(knowledge_.checkTouches({loose_}, states), Violation::None) << angle;
    }
}

TEST_F(SmallSceneKnowledge, ConstrainedBodyOnlyFromItsPushStrip)
{
    // slider is turned by 90 degrees: its push axis is the world y axis, so its strip is |x - x_slider| <=
    // 0.06
    const double halfWidth = scene_.bodies[slider_].push.stripHalfWidth;
    ASSERT_DOUBLE_EQ(halfWidth, 0.06);
    BodyState slider = start_[sliderMoving_];
    for (double x : {-0.059, -0.03, 0.0, 0.03, 0.059})
        for (double y : {-0.18, 0.18})
            EXPECT_TRUE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(x, y, 0.08), slider))
                << x << " " << y;
    for (double x : {-0.18, -0.061, 0.061, 0.18})
        EXPECT_FALSE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(x, -0.18, 0.08), slider)) << x;
    // from the side (on the axis' normal through the centre)
    EXPECT_FALSE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(0.18, 0.0, 0.08), slider));

    // the strip moves with the body
    slider.position = Eigen::Vector3d(0.3, 0.2, 0.1);
    EXPECT_TRUE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(0.35, 0.02, 0.08), slider));
    EXPECT_FALSE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(0.05, 0.02, 0.08), slider));
    // and turns with it: turned back to yaw 0, its axis is the world x axis
    slider.orientation = Eigen::Quaterniond::Identity();
    EXPECT_TRUE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(0.12, 0.25, 0.08), slider));
    EXPECT_FALSE(knowledge_.touchAllowed(slider_, Eigen::Vector3d(0.35, 0.02, 0.08), slider));

    BodyStates states = start_;
    states[0].position = Eigen::Vector3d(0.02, -0.18, 0.08);
    EXPECT_EQ(knowledge_.checkTouches({slider_}, states), Violation::None);
    states[0].position = Eigen::Vector3d(-0.18, 0.0, 0.08);
    EXPECT_EQ(knowledge_.checkTouches({slider_}, states), Violation::TouchedOutsideRegion);
}

TEST_F(SmallSceneKnowledge, ConstrainedBodyStaysOnItsAxis)
{
    const PushConstraint &push = scene_.bodies[slider_].push;
    BodyStates states = start_;
    // along the axis (world y): allowed, however far within the body region
    states[sliderMoving_].position.y() = -0.5;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    states[sliderMoving_].position.y() = 0.4;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    // across it: allowed up to the lateral tolerance
    states[sliderMoving_].position.x() = 0.9 * push.lateralTolerance;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    states[sliderMoving_].position.x() = -1.1 * push.lateralTolerance;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::LeftPushAxis);

    // turning: allowed up to the angle tolerance, about any axis
    states = start_;
    const Eigen::Quaterniond startOrientation = start_[sliderMoving_].orientation;
    for (const Eigen::Vector3d &axis :
         std::vector<Eigen::Vector3d>{Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()})
    {
        states[sliderMoving_].orientation =
            Eigen::AngleAxisd(0.9 * push.angleTolerance, axis) * startOrientation;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
        states[sliderMoving_].orientation =
            Eigen::AngleAxisd(1.1 * push.angleTolerance, axis) * startOrientation;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::LeftPushAxis);
    }
    // a free body may move and turn any way
    states = start_;
    states[looseMoving_].position.head<2>() += Eigen::Vector2d(-0.3, 0.2);
    states[looseMoving_].orientation = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
}

TEST_F(SmallSceneKnowledge, RegionsAndSpeeds)
{
    BodyStates states = start_;
    states[0].position.x() = 1.01;  // robot region: [-1, 1]^2
    EXPECT_EQ(knowledge_.checkStates(states), Violation::OutsideRegion);
    states = start_;
    states[looseMoving_].position.x() = 1.21;  // body region: [-1.2, 1.2]^2
    EXPECT_EQ(knowledge_.checkStates(states), Violation::OutsideRegion);

    const PlanningLimits &limits = scene_.limits;
    states = start_;
    states[0].linearVelocity = Eigen::Vector3d(0.6, -0.8, 0.0) * limits.maxRobotSpeed;  // speed: the limit
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    states[0].linearVelocity.y() = -0.81 * limits.maxRobotSpeed;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TooFast);
    states = start_;
    states[looseMoving_].linearVelocity.x() = 1.01 * limits.maxBodySpeed;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TooFast);
    states = start_;
    states[looseMoving_].angularVelocity.z() = 1.01 * limits.maxAngularSpeed;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TooFast);
    // a spinning free cube within the divergence guard is fine (not the original's +-1 rad/s)
    states[looseMoving_].angularVelocity.z() = 5.0;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
}

TEST_F(SmallSceneKnowledge, RobotOverlappingAFixedFootprint)
{
    // a sampled state with the robot centre within its radius of the wall (y from 0.7 to 0.9)
    BodyStates states = start_;
    states[0].position = Eigen::Vector3d(0.0, 0.7 - 0.079, 0.08);
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TouchedFixedBody);
    states[0].position.y() = 0.7 - 0.081;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
}

TEST_F(SmallSceneKnowledge, NonFiniteNumbers)
{
    BodyStates states = start_;
    states[sliderMoving_].linearVelocity.z() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(knowledge_.checkStates(states), Violation::NotFinite);
    states = start_;
    states[0].position.x() = std::numeric_limits<double>::infinity();
    EXPECT_EQ(knowledge_.checkStates(states), Violation::NotFinite);
}

TEST(ManipulationKnowledge, GoalOccupantsOfTheBenchmarkScenes)
{
    for (int n = 1; n <= 3; ++n)
    {
        SCOPED_TRACE("scene " + std::to_string(n));
        const PhysicsScene scene = benchmarkScene(n);
        const ManipulationKnowledge knowledge(shared(scene));
        const BodyStates start = startStatesOf(scene);
        std::vector<std::size_t> expected;
        const std::vector<std::size_t> movable = scene.movableBodies();
        for (std::size_t i = 0; i < movable.size(); ++i)
            if (robotOnGoalWouldOverlap(scene, movable[i], start[i + 1]))
                expected.push_back(i + 1);
        EXPECT_EQ(knowledge.goalOccupants(start), expected);
        EXPECT_TRUE(knowledge.fixedBodiesOnGoal().empty());
        if (n == 1)
        {
            EXPECT_TRUE(expected.empty());
        }
        if (n == 3)
        {
            EXPECT_EQ(expected, std::vector<std::size_t>{movingIndex(scene, "cube4")});
        }
    }
    // scene 3's occupant, named the way the app reports it
    const PhysicsScene scene3 = benchmarkScene(3);
    const PhysicsWorld world(shared(scene3));
    const std::vector<std::size_t> occupants =
        ManipulationKnowledge(shared(scene3)).goalOccupants(world.startStates());
    ASSERT_EQ(occupants.size(), 1u);
    EXPECT_EQ(world.movingBodyName(occupants.front()), "cube4");
}

TEST(ManipulationKnowledge, ClearGoalSlidesTheConstrainedCubeAlongItsAxis)
{
    const PhysicsScene scene = benchmarkScene(3);
    const ManipulationKnowledge knowledge(shared(scene));
    const BodyStates start = startStatesOf(scene);
    const std::size_t cube4 = movingIndex(scene, "cube4");
    const PhysicsShape &shape = scene.bodies[scene.bodyIndex("cube4")].shape;
    const Eigen::Vector2d goal = scene.goal.centre;
    const double r = scene.robot.radius;
    const double clearance = 0.02;
    ASSERT_LT(footprintDistance(shape, start[cube4].position.head<2>(), 0.0, goal), r);

    BodyStates cleared = start;
    knowledge.clearGoal(cleared, goal, clearance);
    const BodyState &moved = cleared[cube4];
    // along its push axis (world x) only: y, z and the orientation are untouched
    EXPECT_TRUE(sameBits(moved.position.y(), start[cube4].position.y()));
    EXPECT_TRUE(sameBits(moved.position.z(), start[cube4].position.z()));
    EXPECT_TRUE(moved.orientation.coeffs() == start[cube4].orientation.coeffs());
    // the robot at the goal centre no longer overlaps it, with the clearance to spare
    EXPECT_GE(footprintDistance(shape, moved.position.head<2>(), yawOf(moved.orientation), goal),
              r + clearance - 1e-9);
    // the nearer side: the cube's west face must pass x = 0.92 + r + clearance (a shift of 0.12 m east),
    // against 0.28 m west for its east face to pass 0.92 - r - clearance
    const double east = goal.x() + r + clearance + 0.5 * shape.boxSize.x() - start[cube4].position.x();
    EXPECT_GE(moved.position.x() - start[cube4].position.x(), east - 1e-9);
    EXPECT_LT(moved.position.x() - start[cube4].position.x(), east + 0.011);  // searched in 1 cm steps
    // it still keeps the rules: on its axis, in the body region
    EXPECT_EQ(knowledge.checkStates(cleared), Violation::None);
    // nothing else moved
    for (std::size_t i = 0; i < start.size(); ++i)
        if (i != cube4)
        {
            EXPECT_TRUE(sameBits(BodyStates{cleared[i]}, BodyStates{start[i]})) << i;
        }
}

TEST(ManipulationKnowledge, ClearGoalMovesAFreeCubeStraightAway)
{
    PhysicsScene scene = smallScene();
    const ManipulationKnowledge knowledge(shared(scene));
    BodyStates states = startStatesOf(scene);
    const std::size_t loose = movingIndex(scene, "loose");
    const PhysicsShape &shape = scene.bodies[scene.bodyIndex("loose")].shape;
    const Eigen::Vector2d robotGoal = scene.goal.centre + Eigen::Vector2d(0.03, 0.02);
    // the free cube put next to the goal, overlapping a robot there
    states[loose].position.head<2>() = robotGoal + Eigen::Vector2d(-0.12, 0.05);
    const Eigen::Vector2d before = states[loose].position.head<2>();
    ASSERT_LT(footprintDistance(shape, before, 0.0, robotGoal), scene.robot.radius);

    knowledge.clearGoal(states, robotGoal, 0.02);
    const Eigen::Vector2d after = states[loose].position.head<2>();
    EXPECT_GE(footprintDistance(shape, after, 0.0, robotGoal), scene.robot.radius + 0.02 - 1e-9);
    // straight away from the robot's goal position
    const Eigen::Vector2d away = (before - robotGoal).normalized();
    const Eigen::Vector2d shift = after - before;
    EXPECT_GT(shift.dot(away), 0.0);
    EXPECT_NEAR(away.x() * shift.y() - away.y() * shift.x(), 0.0, 1e-9);
}

TEST(ManipulationKnowledge, FixedBodyOnTheGoal)
{
    PhysicsScene scene = smallScene();
    const std::size_t wall = scene.bodyIndex("wall");
    scene.bodies[wall].start.translation() = Eigen::Vector3d(0.8, -0.6, 0.1);  // y from -0.7 to -0.5
    // the goal (0.8, -0.8) is 0.1 m from the wall: the robot (0.08) fits there
    EXPECT_TRUE(ManipulationKnowledge(shared(scene)).fixedBodiesOnGoal().empty());
    scene.bodies[wall].start.translation().y() = -0.65;  // 0.05 m from the goal
    EXPECT_EQ(ManipulationKnowledge(shared(scene)).fixedBodiesOnGoal(), std::vector<std::size_t>{wall});
}

// --- each rule broken by a little, and kept by a little --------------------------------------------------

TEST(ManipulationKnowledge, NeedsAScene)
{
    try
    {
        ManipulationKnowledge knowledge(nullptr);
        ADD_FAILURE() << "no exception for a null scene";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_EQ(std::string(e.what()), "ManipulationKnowledge: needs a scene, got none");
    }
}

TEST_F(SmallSceneKnowledge, TouchingTheConstrainedBodyJustInsideAndOutsideItsStrip)
{
    // the strip is |x| <= 0.06 (push axis = world y); the robot touches the slider's south face
    BodyStates states = start_;
    for (double x : {-0.0599, 0.0599})
    {
        states[0].position = Eigen::Vector3d(x, -0.18, 0.08);
        EXPECT_EQ(knowledge_.checkTouches({slider_}, states), Violation::None) << x;
    }
    for (double x : {-0.0601, 0.0601})
    {
        states[0].position = Eigen::Vector3d(x, -0.18, 0.08);
        EXPECT_EQ(knowledge_.checkTouches({slider_}, states), Violation::TouchedOutsideRegion) << x;
    }
    // the first broken rule counts: a fixed body after it is not reached
    EXPECT_EQ(knowledge_.checkTouches({loose_, slider_, wall_}, states), Violation::TouchedOutsideRegion);
}

TEST_F(SmallSceneKnowledge, RobotJustInsideAndOutsideItsRegion)
{
    // robot region: [-1, 1]^2, edges included
    BodyStates states = start_;
    for (const Eigen::Vector2d &inside : {Eigen::Vector2d(-0.999, -0.8), Eigen::Vector2d(-0.8, -0.999),
                                          Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(0.999, -0.999)})
    {
        states[0].position.head<2>() = inside;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::None) << inside.transpose();
    }
    for (const Eigen::Vector2d &outside : {Eigen::Vector2d(-1.001, -0.8), Eigen::Vector2d(-0.8, -1.001),
                                           Eigen::Vector2d(1.001, -0.8), Eigen::Vector2d(-0.8, 1.001)})
    {
        states[0].position.head<2>() = outside;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::OutsideRegion) << outside.transpose();
    }
}

TEST_F(SmallSceneKnowledge, BodiesJustInsideAndOutsideTheirRegion)
{
    // body region: [-1.2, 1.2]^2
    BodyStates states = start_;
    states[looseMoving_].position.x() = 1.199;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    states[looseMoving_].position.y() = -1.201;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::OutsideRegion);
    // the slider along its axis (world y), out of the region: the region is checked, not the axis
    states = start_;
    states[sliderMoving_].position.y() = 1.199;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    states[sliderMoving_].position.y() = 1.201;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::OutsideRegion);
}

TEST_F(SmallSceneKnowledge, RobotAngularSpeedLimitBoundsTheNorm)
{
    const double limit = scene_.limits.maxAngularSpeed;
    BodyStates states = start_;
    states[0].angularVelocity = Eigen::Vector3d(0.57, -0.57, 0.57) * limit;  // norm 0.987 limit
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    states[0].angularVelocity.z() = 0.6 * limit;  // norm 1.005 limit, each component below it
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TooFast);
}

TEST_F(SmallSceneKnowledge, RobotLinearSpeedLimitBoundsTheHorizontalSpeed)
{
    const double limit = scene_.limits.maxRobotSpeed;
    BodyStates states = start_;
    // each component within the limit, the speed (the norm) above it: a bound per component let
    // a diagonal motion go 1.41 times as fast
    states[0].linearVelocity = Eigen::Vector3d(0.8, -0.8, 0.0) * limit;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TooFast);
    states[0].linearVelocity = Eigen::Vector3d(0.7, -0.7, 0.0) * limit;  // speed 0.99 limit
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
    // the vertical velocity of a sphere on the floor does not count
    states[0].linearVelocity.z() = 2.0 * limit;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
}

TEST_F(SmallSceneKnowledge, BodySpeedLimitsBoundTheNorm)
{
    const PlanningLimits &limits = scene_.limits;
    for (std::size_t moving : {looseMoving_, sliderMoving_})
    {
        SCOPED_TRACE(moving);
        BodyStates states = start_;
        states[moving].linearVelocity = Eigen::Vector3d(0.57, -0.57, 0.57) * limits.maxBodySpeed;
        states[moving].angularVelocity = Eigen::Vector3d(-0.57, 0.57, 0.57) * limits.maxAngularSpeed;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
        for (int k = 0; k < 3; ++k)
        {
            BodyStates fast = states;
            fast[moving].linearVelocity[k] *= 0.6 / 0.57;
            EXPECT_EQ(knowledge_.checkStates(fast), Violation::TooFast) << "linear " << k;
            fast = states;
            fast[moving].angularVelocity[k] *= 0.6 / 0.57;
            EXPECT_EQ(knowledge_.checkStates(fast), Violation::TooFast) << "angular " << k;
        }
    }
}

TEST_F(SmallSceneKnowledge, AMovableBodyLeaningBeyondTheToleranceTippedOver)
{
    const double tolerance = ManipulationKnowledge::TIP_TOLERANCE;
    for (std::size_t moving : {looseMoving_, sliderMoving_})
        for (const Eigen::Vector3d &axis : std::vector<Eigen::Vector3d>{
                 Eigen::Vector3d::UnitX(), Eigen::Vector3d(1.0, 1.0, 0.0).normalized()})
        {
            SCOPED_TRACE(::testing::Message() << moving << " about " << axis.transpose());
            BodyStates states = start_;
            states[moving].orientation =
                Eigen::AngleAxisd(tolerance + 0.01, axis) * start_[moving].orientation;
            EXPECT_EQ(knowledge_.checkStates(states), Violation::TippedOver);
            states[moving].orientation =
                Eigen::AngleAxisd(tolerance - 0.01, axis) * start_[moving].orientation;
            // within it the free cube is fine (the slider turned beyond its own angle tolerance)
            EXPECT_EQ(knowledge_.checkStates(states),
                      moving == looseMoving_ ? Violation::None : Violation::LeftPushAxis);
        }
    // turning about the vertical is no lean
    BodyStates states = start_;
    states[looseMoving_].orientation =
        Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()) * start_[looseMoving_].orientation;
    EXPECT_EQ(knowledge_.checkStates(states), Violation::None);
}

TEST(ManipulationKnowledge, PenetrationJustWithinAndBeyondTheSinkTolerance)
{
    const double tolerance = ManipulationKnowledge::SINK_TOLERANCE;
    EXPECT_EQ(ManipulationKnowledge::checkPenetration(0.0), Violation::None);
    EXPECT_EQ(ManipulationKnowledge::checkPenetration(0.99 * tolerance), Violation::None);
    EXPECT_EQ(ManipulationKnowledge::checkPenetration(1.01 * tolerance), Violation::SankIn);
}

TEST_F(SmallSceneKnowledge, EveryNonFiniteNumberIsCaught)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (std::size_t moving : {std::size_t{0}, looseMoving_, sliderMoving_})
    {
        SCOPED_TRACE(moving);
        BodyStates states = start_;
        states[moving].orientation.coeffs().w() = nan;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::NotFinite);
        states = start_;
        states[moving].angularVelocity.y() = -inf;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::NotFinite);
        states = start_;
        states[moving].position.z() = nan;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::NotFinite);
        states = start_;
        states[moving].linearVelocity.x() = inf;
        EXPECT_EQ(knowledge_.checkStates(states), Violation::NotFinite);
    }
    // the largest finite numbers are finite: another rule decides
    BodyStates states = start_;
    states[looseMoving_].linearVelocity.x() = std::numeric_limits<double>::max();
    EXPECT_EQ(knowledge_.checkStates(states), Violation::TooFast);
}

TEST_F(SmallSceneKnowledge, GoalOccupantJustInsideAndOutsideTheGoalsReach)
{
    // the goal (0.8, -0.8), radius 0.1, robot radius 0.08: a body is an occupant when its footprint comes
    // within 0.18 of the goal centre; the loose cube's east face is at x + 0.1
    ASSERT_DOUBLE_EQ(scene_.goal.radius + scene_.robot.radius, 0.18);
    BodyStates states = start_;
    states[looseMoving_].position.head<2>() = Eigen::Vector2d(0.8 - 0.18 - 0.1 + 0.001, -0.8);
    EXPECT_EQ(knowledge_.goalOccupants(states), std::vector<std::size_t>{looseMoving_});
    states[looseMoving_].position.x() = 0.8 - 0.18 - 0.1 - 0.001;
    EXPECT_TRUE(knowledge_.goalOccupants(states).empty());
    // from the north, and the slider as well
    states = start_;
    states[sliderMoving_].position.head<2>() = Eigen::Vector2d(0.8, -0.8 + 0.18 + 0.1 - 0.001);
    EXPECT_EQ(knowledge_.goalOccupants(states), std::vector<std::size_t>{sliderMoving_});
    states[sliderMoving_].position.y() = -0.8 + 0.18 + 0.1 + 0.001;
    EXPECT_TRUE(knowledge_.goalOccupants(states).empty());
}

TEST(ManipulationKnowledge, FixedBodyJustOnAndOffTheGoal)
{
    // the wall (1 m x 0.2 m) just north of the goal (0.8, -0.8): its south face is at y - 0.1
    PhysicsScene scene = smallScene();
    const std::size_t wall = scene.bodyIndex("wall");
    const double reach = scene.robot.radius;  // a fixed body covers the goal within the robot's radius
    scene.bodies[wall].start.translation() = Eigen::Vector3d(0.8, -0.8 + 0.1 + reach - 0.001, 0.1);
    EXPECT_EQ(ManipulationKnowledge(shared(scene)).fixedBodiesOnGoal(), std::vector<std::size_t>{wall});
    scene.bodies[wall].start.translation().y() = -0.8 + 0.1 + reach + 0.001;
    EXPECT_TRUE(ManipulationKnowledge(shared(scene)).fixedBodiesOnGoal().empty());
}
