// Tests for Transit.
#include "ompl_mm/geometric/ManipulationSetup.h"
#include "ompl_mm/primitives/Transit.h"
#include "ompl_mm/scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
namespace ob = ompl::base;

namespace
{
    class MobileTransit : public ::testing::Test
    {
    protected:
        MobileTransit()
            : setup_(loadScene(OMPL_MM_SCENES_DIR "/mobile_blocked.xml")),
              space_(*setup_.manipulationSpace()),
              transit_(&space_),
              trajectory_(&space_)
        {
            from_ = space_.cloneState(setup_.getProblemDefinition()->getStartState(0));
            to_ = space_.cloneState(from_);
        }
        ~MobileTransit() override
        {
            space_.freeState(from_);
            space_.freeState(to_);
        }

        void robot(ob::State *s, double x, double y)
        {
            space_.robotValues(s)[0] = x;
            space_.robotValues(s)[1] = y;
        }

        ManipulationSetup setup_;
        const ManipulationStateSpace &space_;
        Transit transit_;
        Trajectory trajectory_;
        ob::State *from_;
        ob::State *to_;
    };
}  // namespace

TEST_F(MobileTransit, NameAndKind)
{
    EXPECT_EQ(transit_.name(), "transit");
    EXPECT_EQ(transit_.kind(), PrimitiveKind::Transit);
}

TEST_F(MobileTransit, UsefulWhenOnlyTheRobotMoves)
{
    robot(to_, 0.0, 0.0);
    EXPECT_TRUE(transit_.isUseful(from_, to_));
    EXPECT_TRUE(transit_.isUseful(to_, from_));
}

TEST_F(MobileTransit, NotUsefulWhenTheRobotStays)
{
    EXPECT_FALSE(transit_.isUseful(from_, to_));
}

TEST_F(MobileTransit, NotUsefulWhenAnObjectMoves)
{
    robot(to_, 0.0, 0.0);
    space_.setObjectPose(to_, 1, {Eigen::Vector3d(1.0, -0.1, 0.0), 0.0});
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
    robot(to_, 0.0, 0.0);
    EXPECT_FALSE(transit_.isUseful(from_, to_));
}

TEST_F(MobileTransit, PropagateAppendsTheTargetRobotWithTheSourceObjects)
{
    robot(to_, -0.4, 1.2);
    // objects of `to` that differ are not taken: a transit moves only the robot
    space_.setObjectPose(to_, 2, {Eigen::Vector3d(-0.9, -0.9, 0.0), 0.0});
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
    robot(to_, 0.0, 0.0);
    trajectory_.reset(from_);
    ASSERT_TRUE(transit_.propagate(from_, to_, trajectory_));
    ob::State *third = space_.cloneState(to_);
    robot(third, 1.0, -2.0);
    ASSERT_TRUE(transit_.propagate(trajectory_.back(), third, trajectory_));
    ASSERT_EQ(trajectory_.size(), 3u);
    EXPECT_TRUE(space_.equalStates(trajectory_.state(1), to_));
    EXPECT_TRUE(space_.equalStates(trajectory_.state(2), third));
    space_.freeState(third);
}
