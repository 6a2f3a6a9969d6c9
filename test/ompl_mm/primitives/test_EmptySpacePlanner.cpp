// Tests for EmptySpacePlanner.
#include "ompl_mm/primitives/EmptySpacePlanner.h"
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mm/primitives/Transit.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;
using Outcome = EmptySpacePlanner::Outcome;

namespace
{
    constexpr unsigned int OBJ2 = 1, OBJ4 = 3;

    class MobileEsp : public MobileBlockedTest
    {
    protected:
        MobileEsp() { rng_.setLocalSeed(5); }

        /** Every segment does what its label says: a transit moves no object, a push only its own. */
        void expectSegmentsMatchLabels(const Trajectory &t) const
        {
            for (std::size_t k = 0; k + 1 < t.size(); ++k)
                for (unsigned int i = 0; i < space_.objectCount(); ++i)
                    if (space_.objectMoves(t.state(k), t.state(k + 1), i))
                    {
                        EXPECT_EQ(t.label(k).kind, PrimitiveKind::Push) << "segment " << k;
                        EXPECT_EQ(t.label(k).object, static_cast<int>(i)) << "segment " << k;
                    }
        }

        EmptySpacePlanner esp_{
            &space_, {std::make_shared<Transit>(&space_), std::make_shared<PushMobile>(&space_, 0.41)}};
        Trajectory trajectory_{&space_};
        ompl::RNG rng_;
        ob::State *from_ = startCopy();
        ob::State *to_ = startCopy();
    };
}  // namespace

TEST_F(MobileEsp, RobotOnlyTargetIsOneTransit)
{
    setRobot(space_, to_, 0.0, 0.0);
    ASSERT_EQ(esp_.plan(from_, to_, trajectory_, rng_), Outcome::Reached);
    ASSERT_EQ(trajectory_.size(), 2u);
    EXPECT_TRUE(space_.equalStates(trajectory_.state(0), from_));
    EXPECT_TRUE(space_.equalStates(trajectory_.back(), to_));
    EXPECT_EQ(trajectory_.label(0), (SegmentLabel{PrimitiveKind::Transit, -1}));
}

TEST_F(MobileEsp, SlidingObjectIsPushedThenTheRobotLeaves)
{
    setObject(space_, to_, OBJ2, 1.3, -0.1);
    setRobot(space_, to_, 0.0, 0.0);
    ASSERT_EQ(esp_.plan(from_, to_, trajectory_, rng_), Outcome::Reached);
    EXPECT_TRUE(space_.equalStates(trajectory_.back(), to_));
    // to the standoff, the push, to the robot's target: the only order that works
    ASSERT_EQ(trajectory_.size(), 4u);
    EXPECT_EQ(trajectory_.label(0), (SegmentLabel{PrimitiveKind::Transit, -1}));
    EXPECT_EQ(trajectory_.label(1), (SegmentLabel{PrimitiveKind::Push, static_cast<int>(OBJ2)}));
    EXPECT_EQ(trajectory_.label(2), (SegmentLabel{PrimitiveKind::Transit, -1}));
    expectSegmentsMatchLabels(trajectory_);
}

TEST_F(MobileEsp, TwoSlidingObjectsAreBothPushed)
{
    setObject(space_, to_, OBJ2, 1.0, -0.4);
    setObject(space_, to_, OBJ4, 0.6, 1.9);
    setRobot(space_, to_, 0.0, 0.0);
    ASSERT_EQ(esp_.plan(from_, to_, trajectory_, rng_), Outcome::Reached);
    EXPECT_TRUE(space_.equalStates(trajectory_.back(), to_));
    unsigned int pushes2 = 0, pushes4 = 0;
    for (std::size_t k = 0; k + 1 < trajectory_.size(); ++k)
    {
        pushes2 += trajectory_.label(k) == SegmentLabel{PrimitiveKind::Push, static_cast<int>(OBJ2)};
        pushes4 += trajectory_.label(k) == SegmentLabel{PrimitiveKind::Push, static_cast<int>(OBJ4)};
    }
    EXPECT_EQ(pushes2, 1u);
    EXPECT_EQ(pushes4, 1u);
    expectSegmentsMatchLabels(trajectory_);
}

TEST_F(MobileEsp, EqualStatesAreAlreadyThere)
{
    // to_ is a copy of the start
    EXPECT_EQ(esp_.plan(from_, to_, trajectory_, rng_), Outcome::AlreadyThere);
    ASSERT_EQ(trajectory_.size(), 1u);
    EXPECT_TRUE(space_.equalStates(trajectory_.back(), from_));
}

TEST_F(MobileEsp, LiftedTargetIsNeverReached)
{
    setObject(space_, to_, OBJ2, 0.8, -0.1, 0.3);
    EXPECT_EQ(esp_.plan(from_, to_, trajectory_, rng_), Outcome::Failed);
    EXPECT_EQ(trajectory_.size(), 1u);
    setRobot(space_, to_, 0.0, 0.0);
    setObject(space_, to_, OBJ4, 0.6, 1.9);
    const Outcome outcome = esp_.plan(from_, to_, trajectory_, rng_);
    EXPECT_TRUE(outcome == Outcome::Failed || outcome == Outcome::Partial);
    EXPECT_FALSE(space_.equalStates(trajectory_.back(), to_));
}

TEST_F(MobileEsp, UnreachableTurnGivesPartial)
{
    // no primitive turns objects: obj2 can be pushed, obj4's new yaw stays out of reach
    setObject(space_, to_, OBJ2, 1.3, -0.1);
    space_.setObjectPose(to_, OBJ4, {space_.objectPosition(from_, OBJ4), 1.0});
    setRobot(space_, to_, 0.0, 0.0);
    ASSERT_EQ(esp_.plan(from_, to_, trajectory_, rng_), Outcome::Partial);
    EXPECT_GT(trajectory_.size(), 1u);
    EXPECT_FALSE(space_.objectMoves(trajectory_.back(), to_, OBJ2));
    EXPECT_TRUE(space_.objectMoves(trajectory_.back(), to_, OBJ4));
    expectSegmentsMatchLabels(trajectory_);
}

TEST_F(MobileEsp, NoPrimitivesFails)
{
    EmptySpacePlanner empty(&space_, {});
    setRobot(space_, to_, 0.0, 0.0);
    EXPECT_EQ(empty.plan(from_, to_, trajectory_, rng_), Outcome::Failed);
    EXPECT_TRUE(empty.primitives().empty());
    EXPECT_EQ(esp_.primitives().size(), 2u);
}

TEST_F(MobileEsp, SameSeedSameTrajectory)
{
    setObject(space_, to_, OBJ2, 1.0, -0.4);
    setObject(space_, to_, OBJ4, 0.6, 1.9);
    setRobot(space_, to_, -0.5, 1.0);
    Trajectory other(&space_);
    for (int run = 0; run < 5; ++run)
    {
        ompl::RNG a, b;
        a.setLocalSeed(5 + run);
        b.setLocalSeed(5 + run);
        const Outcome first = esp_.plan(from_, to_, trajectory_, a);
        const Outcome second = esp_.plan(from_, to_, other, b);
        EXPECT_EQ(first, second);
        ASSERT_EQ(trajectory_.size(), other.size());
        for (std::size_t k = 0; k < other.size(); ++k)
        {
            EXPECT_TRUE(space_.equalStates(trajectory_.state(k), other.state(k))) << run << " " << k;
            if (k + 1 < other.size())
            {
                EXPECT_EQ(trajectory_.label(k), other.label(k)) << run << " " << k;
            }
        }
    }
}
