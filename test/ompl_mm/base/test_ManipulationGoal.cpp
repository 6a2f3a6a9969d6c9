// Tests for ManipulationGoal.
#include "ompl_mm/base/ManipulationGoal.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr unsigned int OBJ1 = 0, OBJ3 = 2;

    class MobileGoal : public MobileBlockedTest
    {
    protected:
        /** The start with the robot and obj3 moved to their goals. */
        void makeGoalState()
        {
            setRobot(space_, state_, 0.0, 0.0);
            setObject(space_, state_, OBJ3, -0.9, -0.9);
        }

        const ManipulationGoal &goal_ = *setup_.manipulationGoal();
        ob::State *state_ = startCopy();
    };
}  // namespace

TEST_F(MobileGoal, StartIsNotSatisfied)
{
    EXPECT_FALSE(goal_.isSatisfied(state_));
    // the robot misses by |1.9| - tolerance, obj3 by |-1.5 + 0.9| - tolerance: the largest counts
    EXPECT_NEAR(goal_.distanceGoal(state_), 1.9 - 0.01, 1e-12);
    EXPECT_TRUE(goal_.constrainsRobot());
    EXPECT_TRUE(goal_.constrainsObject(OBJ3));
    EXPECT_FALSE(goal_.constrainsObject(OBJ1));
}

TEST_F(MobileGoal, RobotAndObj3AtTheirTargetsSatisfy)
{
    makeGoalState();
    double distance = -1.0;
    EXPECT_TRUE(goal_.isSatisfied(state_, &distance));
    EXPECT_EQ(distance, 0.0);
    // other objects anywhere on the floor, any yaw of obj3, within tolerance
    space_.setObjectPose(state_, OBJ1, {Eigen::Vector3d(2.2, -2.2, 0.0), 1.0});
    space_.setObjectPose(state_, OBJ3, {Eigen::Vector3d(-0.905, -0.895, 0.0), -2.0});
    space_.robotValues(state_)[0] = 0.009;
    EXPECT_TRUE(goal_.isSatisfied(state_));
}

TEST_F(MobileGoal, DistanceIsTheExcessOverTolerance)
{
    makeGoalState();
    space_.robotValues(state_)[0] = 0.02;
    EXPECT_FALSE(goal_.isSatisfied(state_));
    EXPECT_NEAR(goal_.distanceGoal(state_), 0.02 - 0.01, 1e-12);
    space_.setObjectPose(state_, OBJ3, {Eigen::Vector3d(-0.9, -0.95, 0.0), 0.0});
    EXPECT_NEAR(goal_.distanceGoal(state_), 0.05 - 0.01, 1e-12);  // the larger excess
}

TEST_F(MobileGoal, LiftedObjectIsNotSatisfied)
{
    makeGoalState();
    space_.setObjectPose(state_, OBJ3, {Eigen::Vector3d(-0.9, -0.9, 0.3), 0.0});
    EXPECT_FALSE(goal_.isSatisfied(state_));
    EXPECT_NEAR(goal_.distanceGoal(state_), 1.0, 1e-12);  // z is don't-care; 1 per unsupported object
    makeGoalState();
    space_.setObjectPose(state_, OBJ1, {Eigen::Vector3d(1.0, 1.0, 0.3), 0.0});
    EXPECT_FALSE(goal_.isSatisfied(state_));
}

TEST_F(MobileGoal, CompleteAllUndefinedGivesAGoalState)
{
    PartialState sample(&space_);
    sample.setRobotDefined(false);
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
        sample.setObjectDefined(i, false);
    ompl::RNG rng;
    rng.setLocalSeed(3);
    ob::State *out = space_.allocState();
    for (int trial = 0; trial < 20; ++trial)
    {
        goal_.complete(sample, out, rng);
        EXPECT_DOUBLE_EQ(space_.robotValues(out)[0], 0.0);
        EXPECT_DOUBLE_EQ(space_.robotValues(out)[1], 0.0);
        const ObjectPose obj3 = space_.objectPose(out, OBJ3);
        EXPECT_EQ(obj3.position, Eigen::Vector3d(-0.9, -0.9, 0.0));
        EXPECT_DOUBLE_EQ(obj3.yaw, 0.0);  // the start yaw
        for (unsigned int i = 0; i < space_.objectCount(); ++i)
        {
            const Eigen::Vector3d p = space_.objectPosition(out, i);
            EXPECT_EQ(p.z(), 0.0);
            EXPECT_LE(std::abs(p.x()), 2.5);
            EXPECT_LE(std::abs(p.y()), 2.5);
        }
        EXPECT_TRUE(goal_.isSatisfied(out));
    }
    space_.freeState(out);
}

TEST_F(MobileGoal, CompleteKeepsDefinedPartsTheGoalLeavesFree)
{
    PartialState sample(&space_);
    space_.copyState(sample.state(), state_);
    space_.setObjectPose(sample.state(), OBJ1, {Eigen::Vector3d(1.0, 1.0, 0.0), 0.0});
    space_.setObjectPose(sample.state(), OBJ3, {Eigen::Vector3d(0.5, 0.5, 0.0), 0.0});
    space_.robotValues(sample.state())[0] = 1.0;
    for (unsigned int i = 1; i < space_.objectCount(); ++i)
        sample.setObjectDefined(i, i == OBJ3);
    ompl::RNG rng;
    rng.setLocalSeed(4);
    ob::State *out = space_.allocState();
    goal_.complete(sample, out, rng);
    EXPECT_EQ(space_.objectPosition(out, OBJ1), Eigen::Vector3d(1.0, 1.0, 0.0));
    // the goal wins where it defines a coordinate
    EXPECT_EQ(space_.objectPosition(out, OBJ3), Eigen::Vector3d(-0.9, -0.9, 0.0));
    EXPECT_DOUBLE_EQ(space_.robotValues(out)[0], 0.0);
    EXPECT_TRUE(goal_.isSatisfied(out));

    // a defined object that rests nowhere is replaced by one on the floor
    space_.setObjectPose(sample.state(), OBJ1, {Eigen::Vector3d(1.0, 1.0, 0.3), 0.0});
    goal_.complete(sample, out, rng);
    EXPECT_GE(space_.restingSurface(out, OBJ1), 0);
    EXPECT_TRUE(goal_.isSatisfied(out));
    space_.freeState(out);
}

TEST_F(MobileGoal, NanCoordinateIsNotSatisfied)
{
    makeGoalState();
    space_.robotValues(state_)[0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(goal_.isSatisfied(state_));
    EXPECT_GT(goal_.distanceGoal(state_), 0.0);
}

TEST_F(MobileGoal, YawGoalUsesTheShortAngle)
{
    // the goal alone: a ManipulationSetup rejects a yaw goal that no primitive of the scene can turn to
    Scene scene = mobileBlockedScene();
    scene.objectGoals[0].yaw = 3.1;
    auto space = std::make_shared<ManipulationStateSpace>(makeModel(scene));
    const ManipulationGoal goal(std::make_shared<ob::SpaceInformation>(space));
    ob::State *s = space->cloneState(state_);
    setRobot(*space, s, 0.0, 0.0);
    setObject(*space, s, OBJ3, -0.9, -0.9, 0.0, -3.1);
    // -3.1 and 3.1 are 2 pi - 6.2 apart
    EXPECT_NEAR(goal.distanceGoal(s), (2 * M_PI - 6.2) - 0.05, 1e-9);
    space->freeState(s);
}

TEST(ManipulationGoalInput, ImpossibleGoalsThrowWithTheSceneLine)
{
    const Scene base = mobileBlockedScene();
    const std::string robotLine = base.robotGoal.where.str() + ": ";
    const std::string objectLine = base.objectGoals.at(0).where.str() + ": ";
    ASSERT_GT(base.robotGoal.where.line, 0);

    // the setup of `scene` fails at `line` with a message containing `part`
    auto expectError = [](const Scene &scene, const std::string &line, const std::string &part)
    {
        const std::string what = setupError(scene);
        EXPECT_TRUE(startsWith(what, line)) << part << ": " << what;
        EXPECT_TRUE(contains(what, part)) << what;
    };

    Scene scene = base;
    scene.robotGoal.joints = {3.0, 0.0};
    expectError(scene, robotLine, "'x'");

    scene = base;
    scene.robotGoal.joints = {0.0};
    expectError(scene, robotLine, "1 joint values");

    scene = base;
    scene.objectGoals[0].position = {3.0, 3.0, std::nullopt};
    expectError(scene, objectLine, "obj3");

    scene = base;
    scene.objectGoals[0].object = "obj9";
    expectError(scene, objectLine, "obj9");
}

TEST(ManipulationGoalInput, GoalOffEverySurfaceInOneCoordinateThrows)
{
    // x = 3 lies beyond the floor whatever y is; z = 0.5 is the height of no surface
    Scene scene = mobileBlockedScene();
    scene.objectGoals[0].position = {3.0, std::nullopt, std::nullopt};
    const std::string line = scene.objectGoals[0].where.str() + ": ";
    std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, line)) << "no ompl_core::InputError for x = 3: '" << what << "'";
    scene.objectGoals[0].position = {std::nullopt, std::nullopt, 0.5};
    what = setupError(scene);
    EXPECT_TRUE(startsWith(what, line)) << "no ompl_core::InputError for z = 0.5: '" << what << "'";
}

TEST(ManipulationGoalInput, RobotGoalOnItsLimitsIsAcceptedAndJustBeyondNamesJointAndValue)
{
    // MOBILE BLOCKED's joints x and y range over [-2.5, 2.5]; either limit itself is a valid goal
    const Scene base = mobileBlockedScene();
    const std::string line = base.robotGoal.where.str() + ": ";
    Scene scene = base;
    scene.obstacles.clear();  // the walls would make a goal at a limit collide
    scene.robotGoal.joints = {2.5, -2.5};
    EXPECT_EQ(setupError(scene), "");
    scene.robotGoal.joints = {-2.5, 2.5};
    EXPECT_EQ(setupError(scene), "");

    scene.robotGoal.joints = {2.5001, 0.0};
    EXPECT_EQ(setupError(scene), line + "goal value 2.500100 of joint 'x' is outside its limits");
    scene.robotGoal.joints = {std::nullopt, -2.5001};
    EXPECT_EQ(setupError(scene), line + "goal value -2.500100 of joint 'y' is outside its limits");
}

TEST(ManipulationGoalInput, RobotGoalNeedsOneValuePerJointOrNone)
{
    // no robot goal at all is fine; otherwise one (possibly "*") value per moving joint
    Scene scene = mobileBlockedScene();
    const std::string line = scene.robotGoal.where.str() + ": ";
    scene.robotGoal.joints.clear();
    EXPECT_EQ(setupError(scene), "");
    scene.robotGoal.joints = {0.0, 0.0, 0.0};
    EXPECT_EQ(setupError(scene), line + "goal has 3 joint values but the robot has 2 moving joints (x, y)");
    scene.robotGoal.joints = {std::nullopt, std::nullopt};
    EXPECT_EQ(setupError(scene), "");
}

TEST(ManipulationGoalInput, ObjectGoalOnTheSurfaceEdgeOrWithinTheRestToleranceIsAccepted)
{
    // the floor spans [-2.5, 2.5] in x and y at height 0, resting within 1e-4
    const Scene base = mobileBlockedScene();
    const std::string offSurface =
        base.objectGoals.at(0).where.str() +
        ": goal of object 'obj3' lies on no support surface, so it can never rest there";
    const std::vector<std::array<GoalCoordinate, 3>> inside{{2.5, -2.5, std::nullopt},
                                                            {-2.5, 2.5, 0.0},
                                                            {std::nullopt, std::nullopt, 0.9e-4},
                                                            {std::nullopt, std::nullopt, -0.9e-4}};
    const std::vector<std::array<GoalCoordinate, 3>> outside{{2.5001, std::nullopt, std::nullopt},
                                                             {std::nullopt, -2.5001, std::nullopt},
                                                             {std::nullopt, std::nullopt, 1.1e-4},
                                                             {std::nullopt, std::nullopt, -1.1e-4}};
    for (const auto &position : inside)
    {
        Scene scene = base;
        scene.obstacles.clear();  // the walls would make a goal on the floor's edge collide
        scene.objectGoals[0].position = position;
        EXPECT_EQ(setupError(scene), "");
    }
    for (const auto &position : outside)
    {
        Scene scene = base;
        scene.objectGoals[0].position = position;
        EXPECT_EQ(setupError(scene), offSurface);
    }
}

TEST(ManipulationGoalInput, GoalForAnUnknownObjectNamesIt)
{
    // a Scene built in code may name an object the loader would have rejected
    Scene scene = mobileBlockedScene();
    scene.objectGoals[0].object = "obj9";
    EXPECT_EQ(setupError(scene), scene.objectGoals[0].where.str() + ": goal names unknown object 'obj9'");
}
