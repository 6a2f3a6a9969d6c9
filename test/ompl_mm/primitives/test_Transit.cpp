// Tests for Transit.
#include "ompl_mm/primitives/Transit.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    class MobileTransit : public MobileBlockedTest
    {
    protected:
        Transit transit_{&space_};
        Trajectory trajectory_{&space_};
        ob::State *from_ = startCopy();
        ob::State *to_ = startCopy();
    };
}  // namespace

TEST_F(MobileTransit, NameAndKind)
{
    EXPECT_EQ(transit_.name(), "transit");
    EXPECT_EQ(transit_.kind(), PrimitiveKind::Transit);
}

TEST_F(MobileTransit, UsefulWhenOnlyTheRobotMoves)
{
    setRobot(space_, to_, 0.0, 0.0);
    EXPECT_TRUE(transit_.isUseful(from_, to_));
    EXPECT_TRUE(transit_.isUseful(to_, from_));
}

TEST_F(MobileTransit, NotUsefulWhenTheRobotStays)
{
    EXPECT_FALSE(transit_.isUseful(from_, to_));
}

TEST_F(MobileTransit, NotUsefulWhenAnObjectMoves)
{
    setRobot(space_, to_, 0.0, 0.0);
    setObject(space_, to_, 1, 1.0, -0.1);
    EXPECT_FALSE(transit_.isUseful(from_, to_));
    // turning an object counts as moving it
    space_.copyObject(to_, from_, 1);
    space_.setObjectPose(to_, 3, {space_.objectPosition(from_, 3), 0.5});
    EXPECT_FALSE(transit_.isUseful(from_, to_));
}

TEST_F(MobileTransit, NotUsefulWhenAnObjectIsLifted)
{
    // the same lifted object in both states: nothing moves, but it rests nowhere
    const ObjectPose lifted{Eigen::Vector3d(-2.0, 0.3, 0.3), 0.0};
    space_.setObjectPose(from_, 0, lifted);
    space_.setObjectPose(to_, 0, lifted);
    setRobot(space_, to_, 0.0, 0.0);
    EXPECT_FALSE(transit_.isUseful(from_, to_));
}

TEST_F(MobileTransit, PropagateAppendsTheTargetRobotWithTheSourceObjects)
{
    setRobot(space_, to_, -0.4, 1.2);
    // objects of `to` that differ are not taken: a transit moves only the robot
    setObject(space_, to_, 2, -0.9, -0.9);
    trajectory_.reset(from_);
    ASSERT_TRUE(transit_.propagate(from_, to_, trajectory_));
    ASSERT_EQ(trajectory_.size(), 2u);
    const ob::State *end = trajectory_.back();
    EXPECT_EQ(space_.robotValues(end)[0], -0.4);
    EXPECT_EQ(space_.robotValues(end)[1], 1.2);
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
        EXPECT_FALSE(space_.objectMoves(from_, end, i)) << i;
    EXPECT_EQ(trajectory_.label(0), (SegmentLabel{PrimitiveKind::Transit, -1}));
    EXPECT_TRUE(space_.equalStates(trajectory_.state(0), from_));
}

TEST_F(MobileTransit, PropagateChains)
{
    setRobot(space_, to_, 0.0, 0.0);
    trajectory_.reset(from_);
    ASSERT_TRUE(transit_.propagate(from_, to_, trajectory_));
    ob::State *third = space_.cloneState(to_);
    setRobot(space_, third, 1.0, -2.0);
    ASSERT_TRUE(transit_.propagate(trajectory_.back(), third, trajectory_));
    ASSERT_EQ(trajectory_.size(), 3u);
    EXPECT_TRUE(space_.equalStates(trajectory_.state(1), to_));
    EXPECT_TRUE(space_.equalStates(trajectory_.state(2), third));
    space_.freeState(third);
}
