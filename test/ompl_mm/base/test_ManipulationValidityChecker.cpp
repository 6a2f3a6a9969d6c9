// Tests for ManipulationValidityChecker.
#include "ompl_mm/base/ManipulationValidityChecker.h"

#include "common/MobileBlocked.h"

#include <ompl/base/SpaceInformation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr double RADIUS = 0.2;  // robot disc and every object of MOBILE BLOCKED

    class MobileChecker : public MobileBlockedTest
    {
    protected:
        void robotAt(double x, double y) { setRobot(space_, state_, x, y); }
        void objectAt(unsigned int i, double x, double y, double z = 0.0)
        {
            setObject(space_, state_, i, x, y, z);
        }

        ManipulationValidityChecker &checker_ = *setup_.validityChecker();
        ob::State *state_ = startCopy();
    };
}  // namespace

TEST_F(MobileChecker, StartIsValid)
{
    EXPECT_TRUE(checker_.isValid(state_));
    EXPECT_EQ(checker_.explain(state_), "");
}

TEST_F(MobileChecker, RobotInsideABlockIsInvalidAndNamed)
{
    robotAt(-1.0, 0.0);  // centre of block1
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "block1")) << why;
    EXPECT_TRUE(contains(why, "robot link 'body'")) << why;
}

TEST_F(MobileChecker, RobotOverlappingAnObjectIsInvalid)
{
    robotAt(0.8 + 0.3, -0.1);  // 0.3 from obj2's centre, less than 2 radii
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "object 'obj2'")) << why;
    EXPECT_TRUE(contains(why, "robot link")) << why;
}

TEST_F(MobileChecker, OverlappingObjectsAreInvalidAndNamed)
{
    objectAt(0, 0.8 + 0.3, -0.1);  // obj1 onto obj2
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "object 'obj1'")) << why;
    EXPECT_TRUE(contains(why, "object 'obj2'")) << why;
}

TEST_F(MobileChecker, ObjectInAWallIsInvalid)
{
    objectAt(0, 2.4, -1.0);  // reaches x = 2.6, the east wall starts at 2.5
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "wall_east")) << why;
    EXPECT_TRUE(contains(why, "obj1")) << why;
}

TEST_F(MobileChecker, JointOutOfLimitsIsInvalidAndNamed)
{
    robotAt(1.9, -2.6);
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "joint 'y'")) << why;
}

TEST_F(MobileChecker, AtMostOneObjectIsHeld)
{
    objectAt(0, -2.0, 0.3, 0.3);  // obj1 lifted: held, nothing else wrong
    EXPECT_TRUE(checker_.isValid(state_)) << checker_.explain(state_);
    objectAt(1, 0.8, -0.1, 0.3);  // obj2 lifted too
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "rest on no surface")) << why;
    EXPECT_TRUE(contains(why, "obj1") && contains(why, "obj2")) << why;
}

TEST_F(MobileChecker, TouchingDistanceBetweenRobotAndObject)
{
    // the robot sphere and obj2's cylinder overlap when their axes are closer than 2 radii
    const Eigen::Vector2d obj2(0.8, -0.1);
    for (double angle : {0.0, 2.0, 2.6, M_PI, -1.3})
    {
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        const Eigen::Vector2d clear = obj2 + (2 * RADIUS + 0.001) * direction;
        const Eigen::Vector2d touching = obj2 + (2 * RADIUS - 0.001) * direction;
        robotAt(clear.x(), clear.y());
        EXPECT_TRUE(checker_.isValid(state_)) << angle << " " << checker_.explain(state_);
        robotAt(touching.x(), touching.y());
        EXPECT_FALSE(checker_.isValid(state_)) << angle;
        EXPECT_TRUE(contains(checker_.explain(state_), "obj2")) << angle;
    }
}

TEST_F(MobileChecker, CountersCountQueries)
{
    checker_.resetCounters();
    EXPECT_EQ(checker_.queryCount(), 0u);
    EXPECT_TRUE(checker_.isValid(state_));
    EXPECT_EQ(checker_.queryCount(), 1u);
    EXPECT_EQ(checker_.freeQueryCount(), 1u);
    robotAt(-1.0, 0.0);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_EQ(checker_.queryCount(), 2u);
    EXPECT_EQ(checker_.freeQueryCount(), 1u);
    checker_.explain(state_);
    robotAt(1.9, 1.9);
    checker_.explain(state_);
    EXPECT_EQ(checker_.queryCount(), 2u);
    EXPECT_EQ(checker_.freeQueryCount(), 1u);
    checker_.resetCounters();
    EXPECT_EQ(checker_.queryCount(), 0u);
    EXPECT_EQ(checker_.freeQueryCount(), 0u);
}

TEST_F(MobileChecker, NanRobotJointIsInvalid)
{
    robotAt(std::numeric_limits<double>::quiet_NaN(), 1.9);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_NE(checker_.explain(state_), "");
}

TEST_F(MobileChecker, NanObjectPoseIsInvalid)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    objectAt(0, nan, 0.3);
    EXPECT_FALSE(checker_.isValid(state_));
    objectAt(0, -2.0, 0.3);
    setObject(space_, state_, 0, -2.0, 0.3, 0.0, nan);
    EXPECT_FALSE(checker_.isValid(state_));
}

TEST(ManipulationValidityCheckerTable, RestingObjectMayTouchItsSurfaceObstacle)
{
    // a table 1 x 1 x 0.43 at (1, 1); a surface on its top; a small cylinder standing there
    Scene scene;
    scene.robot.urdfFile = OMPL_MM_SCENES_DIR "/robots/mobile_disc.urdf";
    scene.robot.toolLink = "body";
    Obstacle table;
    table.name = "table";
    table.shape.kind = Shape::Kind::Box;
    table.shape.boxSize = Eigen::Vector3d(1.0, 1.0, 0.43);
    table.pose.translation() = Eigen::Vector3d(1.0, 1.0, 0.215);
    scene.obstacles.push_back(table);
    SupportSurface top =
        supportSurface("table_top", Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(1.5, 1.5), 0.43);
    top.obstacle = "table";
    scene.surfaces = {supportSurface("floor", Eigen::Vector2d(-2.5, -2.5), Eigen::Vector2d(2.5, 2.5)), top};
    scene.objects.push_back(cylinderObject("cup", 0.1, 0.2));

    auto space = std::make_shared<ManipulationStateSpace>(makeModel(scene));
    auto si = std::make_shared<ob::SpaceInformation>(space);
    ManipulationValidityChecker checker(si);
    ob::State *state = space->allocState();
    setRobot(*space, state, -1.0, -1.0);

    setObject(*space, state, 0, 1.0, 1.0, 0.43);
    ASSERT_EQ(space->restingSurface(state, 0), 1);
    EXPECT_TRUE(checker.isValid(state)) << checker.explain(state);

    // 1 cm lower it rests on nothing (held) and sinks into the table
    setObject(*space, state, 0, 1.0, 1.0, 0.42);
    ASSERT_LT(space->restingSurface(state, 0), 0);
    EXPECT_FALSE(checker.isValid(state));
    const std::string why = checker.explain(state);
    EXPECT_TRUE(contains(why, "table")) << why;
    EXPECT_TRUE(contains(why, "cup")) << why;

    // on the floor beside the table it is valid again; pushed into the table's side it is not
    setObject(*space, state, 0, 0.3, 1.0);
    EXPECT_TRUE(checker.isValid(state)) << checker.explain(state);
    setObject(*space, state, 0, 0.45, 1.0);
    EXPECT_FALSE(checker.isValid(state));
    space->freeState(state);
}

TEST_F(MobileChecker, NonFiniteValuesAreInvalidWithTheirOwnReason)
{
    // infinity or NaN in a joint, an object position or a yaw; checked before anything else
    const double inf = std::numeric_limits<double>::infinity();
    robotAt(inf, 1.9);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_EQ(checker_.explain(state_), "the state has a non-finite value");
    robotAt(1.9, 1.9);
    objectAt(2, -1.5, -inf);
    EXPECT_EQ(checker_.explain(state_), "the state has a non-finite value");
    objectAt(2, -1.5, -1.5);
    setObject(space_, state_, 2, -1.5, -1.5, 0.0, std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(checker_.explain(state_), "the state has a non-finite value");
}

TEST_F(MobileChecker, BothJointLimitsOfBothJointsAreCheckedAndNamed)
{
    // the limits are checked before collisions (beyond them the disc is also in a wall)
    robotAt(2.6, 0.0);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_EQ(checker_.explain(state_), "joint 'x' = 2.600000 is outside [-2.500000, 2.500000]");
    robotAt(-2.6, 0.0);
    EXPECT_EQ(checker_.explain(state_), "joint 'x' = -2.600000 is outside [-2.500000, 2.500000]");
    robotAt(0.0, 2.6);
    EXPECT_EQ(checker_.explain(state_), "joint 'y' = 2.600000 is outside [-2.500000, 2.500000]");
    robotAt(0.0, -2.6);
    EXPECT_EQ(checker_.explain(state_), "joint 'y' = -2.600000 is outside [-2.500000, 2.500000]");
}

TEST_F(MobileChecker, ObjectsWithinTheRestToleranceRestAndBeyondItAreHeld)
{
    // 1e-4 is the rest tolerance: two objects just within it both rest, just beyond it both are held
    objectAt(0, -2.0, 0.3, 0.9e-4);
    objectAt(1, 0.8, -0.1, -0.9e-4);
    EXPECT_TRUE(checker_.isValid(state_)) << checker_.explain(state_);
    objectAt(0, -2.0, 0.3, 1.1e-4);
    EXPECT_TRUE(checker_.isValid(state_)) << checker_.explain(state_);  // one held is allowed
    objectAt(1, 0.8, -0.1, -1.1e-4);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_EQ(checker_.explain(state_), "objects 'obj1' and 'obj2' both rest on no surface");
}

TEST(ManipulationValidityCheckerArm, JointOnItsLimitsIsValidAndJustBeyondIsNot)
{
    // the unit arm's shoulder ranges over [-3, 3]; nothing else can make its states invalid
    auto space = std::make_shared<ManipulationStateSpace>(makeModel(unitArmScene()));
    auto si = std::make_shared<ob::SpaceInformation>(space);
    ManipulationValidityChecker checker(si);
    ob::State *state = space->allocState();
    for (double q : {3.0, -3.0, 0.0})
    {
        space->robotValues(state)[0] = q;
        EXPECT_TRUE(checker.isValid(state)) << q << ": " << checker.explain(state);
    }
    space->robotValues(state)[0] = 3.0001;
    EXPECT_FALSE(checker.isValid(state));
    EXPECT_EQ(checker.explain(state), "joint 'shoulder' = 3.000100 is outside [-3.000000, 3.000000]");
    space->robotValues(state)[0] = -3.0001;
    EXPECT_FALSE(checker.isValid(state));
    EXPECT_EQ(checker.explain(state), "joint 'shoulder' = -3.000100 is outside [-3.000000, 3.000000]");
    space->freeState(state);
}
