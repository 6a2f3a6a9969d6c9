// Tests for ManipulationStateSpace.
#include "ompl_mm/base/ManipulationStateSpace.h"

#include "common/MobileBlocked.h"

#include <ompl/base/ScopedState.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <utility>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    class MobileSpace : public MobileBlockedTest
    {
    protected:
        MobileSpace()
        {
            setup_.getSpaceInformation()->setup();
            start_ = startCopy();
        }

        ob::State *start_;
    };
}  // namespace

TEST_F(MobileSpace, DimensionAndSubspaceNames)
{
    EXPECT_EQ(space_.robotDimension(), 2u);
    EXPECT_EQ(space_.objectCount(), 4u);
    EXPECT_EQ(space_.getDimension(), 2u + 4u * 4u);
    std::vector<double> reals;
    space_.copyToReals(reals, start_);
    ASSERT_EQ(reals.size(), 18u);
    // robot first, then x, y, z, yaw per object in scene order
    EXPECT_DOUBLE_EQ(reals[0], 1.9);
    EXPECT_DOUBLE_EQ(reals[1], 1.9);
    EXPECT_DOUBLE_EQ(reals[2 + 4 * 2 + 0], -1.5);  // obj3 x
    EXPECT_DOUBLE_EQ(reals[2 + 4 * 2 + 1], -1.5);  // obj3 y

    ASSERT_EQ(space_.getSubspaceCount(), 1u + 2u * 4u);
    EXPECT_EQ(space_.getSubspace(0)->getName(), "robot");
    const auto *robot = space_.getSubspace(0)->as<ob::RealVectorStateSpace>();
    EXPECT_EQ(robot->getDimensionName(0), "x");
    EXPECT_EQ(robot->getDimensionName(1), "y");
    for (unsigned int i = 0; i < 4; ++i)
    {
        const std::string name = "obj" + std::to_string(i + 1);
        EXPECT_EQ(space_.getSubspace(1 + 2 * i)->getName(), name + "_position");
        EXPECT_EQ(space_.getSubspace(2 + 2 * i)->getName(), name + "_yaw");
    }
}

TEST_F(MobileSpace, AStateIsOneBlockOfItsOwn)
{
    // every component lies within a few hundred bytes after the compound (one allocation), and
    // clones have blocks of their own that copy the values
    ob::State *state = startCopy();
    const auto *compound = state->as<ManipulationStateSpace::StateType>();
    const auto *begin = reinterpret_cast<const char *>(compound);
    for (unsigned int i = 0; i < space_.getSubspaceCount(); ++i)
    {
        const auto *component = reinterpret_cast<const char *>(compound->components[i]);
        EXPECT_GT(component, begin) << i;
        EXPECT_LT(component, begin + 1024) << i;
    }
    const double *robot = space_.robotValues(state);
    EXPECT_GT(reinterpret_cast<const char *>(robot), begin);
    EXPECT_LT(reinterpret_cast<const char *>(robot), begin + 1024);
    ob::State *clone = space_.cloneState(state);
    EXPECT_TRUE(space_.equalStates(clone, state));
    space_.setObjectPose(clone, 2, {Eigen::Vector3d(0.5, 0.5, 0.0), 0.25});
    EXPECT_EQ(space_.objectPosition(state, 2), Eigen::Vector3d(-1.5, -1.5, 0.0)) << "the clone is apart";
    EXPECT_EQ(space_.objectPose(clone, 2).yaw, 0.25);
    space_.freeState(clone);
}

TEST_F(MobileSpace, ScopedStatePrintsObjectNames)
{
    ob::ScopedState<> state(setup_.getStateSpace());
    state = start_;
    std::ostringstream out;
    out << state;
    const std::string text = out.str();
    EXPECT_NE(text.find("robot ["), std::string::npos) << text;
    for (const char *name : {"obj1", "obj2", "obj3", "obj4"})
        EXPECT_NE(text.find(name), std::string::npos) << text;
}

TEST_F(MobileSpace, ObjectPoseRoundTripAndYawWrap)
{
    ob::State *s = space_.cloneState(start_);
    const ObjectPose pose{Eigen::Vector3d(0.3, -0.7, 0.0), 1.25};
    space_.setObjectPose(s, 1, pose);
    const ObjectPose back = space_.objectPose(s, 1);
    EXPECT_EQ(back.position, pose.position);
    EXPECT_DOUBLE_EQ(back.yaw, 1.25);
    EXPECT_EQ(space_.objectPosition(s, 1), pose.position);
    EXPECT_DOUBLE_EQ(space_.objectYaw(s, 1), 1.25);

    // yaw outside [-pi, pi] wraps to an equivalent angle inside it
    for (double yaw : {4.0, -4.0, 7.5, -10.0, 3.0 * M_PI})
    {
        space_.setObjectPose(s, 2, {Eigen::Vector3d(0, 0, 0), yaw});
        const double wrapped = space_.objectYaw(s, 2);
        EXPECT_LE(std::abs(wrapped), M_PI + 1e-12) << yaw;
        EXPECT_NEAR(std::remainder(wrapped - yaw, 2.0 * M_PI), 0.0, 1e-9) << yaw;
    }
    space_.freeState(s);
}

TEST_F(MobileSpace, MovesDetectsChanges)
{
    ob::State *s = space_.cloneState(start_);
    EXPECT_FALSE(space_.robotMoves(start_, s));
    for (unsigned int i = 0; i < 4; ++i)
        EXPECT_FALSE(space_.objectMoves(start_, s, i));

    setRobot(space_, s, 1.9, 1.8);
    EXPECT_TRUE(space_.robotMoves(start_, s));
    EXPECT_FALSE(space_.objectMoves(start_, s, 0));

    space_.copyState(s, start_);
    setObject(space_, s, 3, 1.2, 1.9, 0.0, 0.1);  // obj4 turns only
    EXPECT_TRUE(space_.objectMoves(start_, s, 3));
    EXPECT_FALSE(space_.objectMoves(start_, s, 2));
    EXPECT_FALSE(space_.robotMoves(start_, s));

    setObject(space_, s, 3, 1.2, 1.9, 1e-12, 0.0);  // below the 1e-9 threshold
    EXPECT_FALSE(space_.objectMoves(start_, s, 3));
    space_.freeState(s);
}

TEST_F(MobileSpace, InterpolateIsLinearForRestingObjects)
{
    ob::State *to = space_.cloneState(start_);
    setRobot(space_, to, 0.5, 1.0);
    setObject(space_, to, 1, 0.3, 0.6, 0.0, 0.0);
    setObject(space_, start_, 0, -2.0, 0.3, 0.0, 0.2);
    setObject(space_, to, 0, -2.0, 0.3, 0.0, 0.5);
    ob::State *at = space_.allocState();
    for (double t : {0.0, 0.3, 1.0})
    {
        space_.interpolate(start_, to, t, at);
        EXPECT_NEAR(space_.robotValues(at)[0], 1.9 + t * (0.5 - 1.9), 1e-12) << t;
        EXPECT_NEAR(space_.robotValues(at)[1], 1.9 + t * (1.0 - 1.9), 1e-12) << t;
        const Eigen::Vector3d expected =
            Eigen::Vector3d(0.8, -0.1, 0) + t * Eigen::Vector3d(0.3 - 0.8, 0.6 + 0.1, 0);
        EXPECT_NEAR((space_.objectPosition(at, 1) - expected).norm(), 0.0, 1e-12) << t;
        EXPECT_NEAR(space_.objectYaw(at, 0), 0.2 + t * 0.3, 1e-12) << t;
        // objects that do not move stay put
        EXPECT_FALSE(space_.objectMoves(start_, at, 2));
        EXPECT_FALSE(space_.objectMoves(start_, at, 3));
    }
    space_.freeState(at);
    space_.freeState(to);
}

TEST_F(MobileSpace, HeldObjectMovesWithTheTool)
{
    // obj2 lifted 0.3 m rests on no surface: it is held and follows the tool
    const double dx = -0.6, dy = 0.4;
    setRobot(space_, start_, 1.0, 0.0);
    setObject(space_, start_, 1, 0.8, -0.1, 0.3, 0.7);
    ASSERT_LT(space_.restingSurface(start_, 1), 0);
    ob::State *to = space_.cloneState(start_);
    setRobot(space_, to, 1.0 + dx, 0.0 + dy);
    setObject(space_, to, 1, 0.8 + dx, -0.1 + dy, 0.3, 0.7);
    ob::State *at = space_.allocState();
    for (double t : {0.0, 0.25, 0.5, 1.0})
    {
        space_.interpolate(start_, to, t, at);
        const Eigen::Vector3d expected(0.8 + t * dx, -0.1 + t * dy, 0.3);
        EXPECT_NEAR((space_.objectPosition(at, 1) - expected).norm(), 0.0, 1e-12) << t;
        EXPECT_NEAR(space_.objectYaw(at, 1), 0.7, 1e-12) << t;
        const Eigen::Vector3d tool = space_.toolPosition(at);
        EXPECT_NEAR(tool.x(), 1.0 + t * dx, 1e-12);
        EXPECT_NEAR(tool.y(), 0.0 + t * dy, 1e-12);
    }
    space_.freeState(at);
    space_.freeState(to);
}

TEST(ManipulationStateSpaceArm, HeldObjectTurnsWithARevoluteTool)
{
    // one revolute joint about z at (0, 0, 1), hand 0.5 m along the arm: a held object keeps its
    // grasp, so it moves on a circle about the z axis and turns with the arm
    Scene scene = unitArmScene();
    scene.surfaces.push_back(supportSurface("floor", Eigen::Vector2d(-2.0, -2.0), Eigen::Vector2d(2.0, 2.0)));
    scene.objects.push_back(cylinderObject("cup", 0.05, 0.1));
    ManipulationStateSpace space(makeModel(scene));
    ob::State *from = space.allocState();
    ob::State *to = space.allocState();
    ob::State *at = space.allocState();
    const double radius = 0.6, height = 0.8, theta0 = 0.0, theta1 = M_PI / 2;
    space.robotValues(from)[0] = theta0;
    space.robotValues(to)[0] = theta1;
    setObject(space, from, 0, radius, 0, height, 0.0);
    setObject(space, to, 0, 0, radius, height, theta1);
    for (double t : {0.0, 0.25, 0.5, 1.0})
    {
        space.interpolate(from, to, t, at);
        const double theta = theta0 + t * (theta1 - theta0);
        const Eigen::Vector3d expected(radius * std::cos(theta), radius * std::sin(theta), height);
        EXPECT_NEAR((space.objectPosition(at, 0) - expected).norm(), 0.0, 1e-9) << t;
        EXPECT_NEAR(std::remainder(space.objectYaw(at, 0) - theta, 2 * M_PI), 0.0, 1e-9) << t;
    }
    space.freeState(at);
    space.freeState(to);
    space.freeState(from);
}

TEST(ManipulationStateSpaceArm, PickedUpObjectFollowsTheToolFromItsSurface)
{
    // the cup rests on a small table under the hand at the start and is held at the end: picking it
    // up carries it with the hand from the first instant (on the circle, not along the chord)
    Scene scene = unitArmScene();
    scene.surfaces.push_back(
        supportSurface("table", Eigen::Vector2d(0.5, -0.1), Eigen::Vector2d(0.7, 0.1), 0.8));
    scene.objects.push_back(cylinderObject("cup", 0.05, 0.1));
    ManipulationStateSpace space(makeModel(scene));
    ob::State *from = space.allocState();
    ob::State *to = space.allocState();
    ob::State *at = space.allocState();
    const double radius = 0.6, height = 0.8;
    space.robotValues(from)[0] = 0.0;
    space.robotValues(to)[0] = M_PI / 2;
    setObject(space, from, 0, radius, 0, height, 0.0);
    setObject(space, to, 0, 0, radius, height, M_PI / 2);
    ASSERT_GE(space.restingSurface(from, 0), 0);
    ASSERT_LT(space.restingSurface(to, 0), 0);
    for (const auto &[a, b] : {std::pair{from, to}, std::pair{to, from}})  // pick up, and put down
    {
        space.interpolate(a, b, 0.5, at);
        const Eigen::Vector3d onTheCircle(radius * std::cos(M_PI / 4), radius * std::sin(M_PI / 4), height);
        EXPECT_NEAR((space.objectPosition(at, 0) - onTheCircle).norm(), 0.0, 1e-9);
    }
    space.freeState(at);
    space.freeState(to);
    space.freeState(from);
}

TEST_F(MobileSpace, DistanceIsSymmetricAndZeroForEqualStates)
{
    ob::State *other = space_.cloneState(start_);
    EXPECT_DOUBLE_EQ(space_.distance(start_, other), 0.0);
    setRobot(space_, other, -0.4, 1.1);
    setObject(space_, other, 2, -0.9, -0.9, 0.0, 2.0);
    const double d = space_.distance(start_, other);
    EXPECT_GT(d, 0.0);
    EXPECT_DOUBLE_EQ(d, space_.distance(other, start_));
    EXPECT_TRUE(space_.equalStates(start_, start_));
    EXPECT_FALSE(space_.equalStates(start_, other));
    space_.freeState(other);
}

TEST_F(MobileSpace, CollisionResolutionSetsSegmentCount)
{
    ob::State *to = space_.cloneState(start_);
    setRobot(space_, to, 1.9 - 1.2, 1.9 - 0.5);  // displacement 1.3
    for (double step : {0.05, 0.1, 0.3})
    {
        space_.setSegmentResolution(step);
        space_.setup();
        const double expected = std::ceil(1.3 / step);
        const double count = space_.validSegmentCount(start_, to);
        EXPECT_NEAR(count, expected, 1.0) << step;
    }
    space_.freeState(to);
}

TEST_F(MobileSpace, InterpolationStartsAndEndsAtItsEndpoints)
{
    ob::State *to = space_.cloneState(start_);
    ob::State *at = space_.allocState();
    // obj2 held in both states, at a different place relative to the tool
    setObject(space_, start_, 1, 0.8, -0.1, 0.3);
    setObject(space_, to, 1, 0.0, 0.5, 0.3);
    setRobot(space_, to, 1.0, 1.9);
    space_.interpolate(start_, to, 1.0, at);
    EXPECT_NEAR(space_.distance(at, to), 0.0, 1e-9);
    // obj2 resting at the start and held at the end (a pickup)
    setObject(space_, start_, 1, 0.8, -0.1, 0.0);
    space_.interpolate(start_, to, 0.0, at);
    EXPECT_NEAR(space_.distance(at, start_), 0.0, 1e-9);
    EXPECT_NO_THROW(space_.sanityChecks());
    space_.freeState(at);
    space_.freeState(to);
}

TEST(ManipulationStateSpaceArm, InterpolationAtItsEndsGivesTheEndsExactly)
{
    // the joint from 1.1 to its lower limit, -3 (inverse kinematics leaves joints exactly at their
    // limits): 1.1 + (-3 - 1.1) * 1 is -3.0000000000000004 in floating point, out of the limits, so
    // a motion to a valid state would end in an invalid one
    ManipulationStateSpace space(makeModel(unitArmScene()));
    ob::State *from = space.allocState();
    ob::State *to = space.allocState();
    ob::State *at = space.allocState();
    space.robotValues(from)[0] = 1.1;
    space.robotValues(to)[0] = -3.0;
    ASSERT_TRUE(space.satisfiesBounds(to));
    space.interpolate(from, to, 1.0, at);
    EXPECT_EQ(space.robotValues(at)[0], -3.0);
    EXPECT_TRUE(space.satisfiesBounds(at));
    space.interpolate(to, from, 0.0, at);
    EXPECT_EQ(space.robotValues(at)[0], -3.0);
    space.freeState(at);
    space.freeState(to);
    space.freeState(from);
}

TEST(ManipulationStateSampler, NearSamplesKeepTheObjectsAndMoveTheRobotWithinTheDistance)
{
    const ManipulationStateSpacePtr space =
        std::make_shared<ManipulationStateSpace>(makeModel(mobileBlockedScene()));
    const ompl::base::StateSamplerPtr sampler = space->allocStateSampler();
    ompl::base::State *near = space->allocState();
    ompl::base::State *state = space->allocState();
    bool robotMoved = false;
    for (int i = 0; i < 100; ++i)
    {
        sampler->sampleUniform(near);
        sampler->sampleUniformNear(state, near, 0.3);
        for (unsigned int o = 0; o < space->objectCount(); ++o)
            EXPECT_FALSE(space->objectMoves(near, state, o));
        const double *a = space->robotValues(near);
        const double *b = space->robotValues(state);
        EXPECT_LE(std::max(std::abs(a[0] - b[0]), std::abs(a[1] - b[1])), 0.3 + 1e-12);
        robotMoved = robotMoved || space->robotMoves(near, state);
        sampler->sampleGaussian(state, near, 0.1);
        EXPECT_FALSE(space->anyObjectMoves(near, state));
    }
    EXPECT_TRUE(robotMoved);
    space->freeState(near);
    space->freeState(state);
}
