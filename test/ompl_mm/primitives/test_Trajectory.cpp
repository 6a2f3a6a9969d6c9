// Tests for Trajectory.
#include "ompl_mm/primitives/Trajectory.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cstring>
#include <utility>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    class MobileTrajectory : public MobileBlockedTest
    {
    protected:
        MobileTrajectory()
        {
            for (int i = 0; i < 4; ++i)
            {
                states_.push_back(startCopy());
                space_.robotValues(states_.back())[0] = 1.9 - 0.5 * i;
            }
        }

        /** A trajectory through states_[0..n) whose segment i has label {Push, i}. */
        Trajectory make(std::size_t n) const
        {
            Trajectory t(&space_);
            t.reset(states_[0]);
            for (std::size_t i = 1; i < n; ++i)
                t.append(states_[i], {PrimitiveKind::Push, static_cast<int>(i - 1)});
            return t;
        }

        std::vector<ob::State *> states_;
    };
}  // namespace

TEST(PrimitiveKindName, NamesEveryKind)
{
    EXPECT_STREQ(primitiveKindName(PrimitiveKind::Transit), "transit");
    EXPECT_STREQ(primitiveKindName(PrimitiveKind::Push), "push");
    EXPECT_STREQ(primitiveKindName(PrimitiveKind::Pickup), "pickup");
    EXPECT_STREQ(primitiveKindName(PrimitiveKind::Transfer), "transfer");
}

TEST(SegmentLabel, Equality)
{
    const SegmentLabel transit;
    EXPECT_EQ(transit.kind, PrimitiveKind::Transit);
    EXPECT_EQ(transit.object, -1);
    EXPECT_TRUE((SegmentLabel{PrimitiveKind::Push, 2} == SegmentLabel{PrimitiveKind::Push, 2}));
    EXPECT_TRUE((SegmentLabel{PrimitiveKind::Push, 2} != SegmentLabel{PrimitiveKind::Push, 1}));
    EXPECT_TRUE((SegmentLabel{PrimitiveKind::Push, 2} != SegmentLabel{PrimitiveKind::Transfer, 2}));
}

TEST_F(MobileTrajectory, StartsEmpty)
{
    Trajectory t(&space_);
    EXPECT_TRUE(t.empty());
    EXPECT_EQ(t.size(), 0u);
    EXPECT_EQ(t.space(), &space_);
}

TEST_F(MobileTrajectory, AppendCopiesStatesAndLabels)
{
    Trajectory t = make(4);
    ASSERT_EQ(t.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i)
    {
        EXPECT_TRUE(space_.equalStates(t.state(i), states_[i])) << i;
        EXPECT_NE(t.state(i), states_[i]) << "a copy, not the caller's state";
    }
    for (std::size_t i = 0; i + 1 < 4; ++i)
        EXPECT_EQ(t.label(i), (SegmentLabel{PrimitiveKind::Push, static_cast<int>(i)}));
    EXPECT_EQ(t.back(), t.state(3));
    // changing the caller's state afterwards does not change the waypoint
    space_.robotValues(states_[1])[1] = -2.0;
    EXPECT_EQ(space_.robotValues(t.state(1))[1], 1.9);
}

TEST_F(MobileTrajectory, ResetStartsAgain)
{
    Trajectory t = make(4);
    t.reset(states_[2]);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_TRUE(space_.equalStates(t.back(), states_[2]));
    t.append(states_[3], {PrimitiveKind::Transit, -1});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t.label(0), (SegmentLabel{PrimitiveKind::Transit, -1}));
}

TEST_F(MobileTrajectory, TruncateKeepsTheFirstStatesAndTheirLabels)
{
    Trajectory t = make(4);
    t.truncate(2);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_TRUE(space_.equalStates(t.back(), states_[1]));
    EXPECT_EQ(t.label(0), (SegmentLabel{PrimitiveKind::Push, 0}));
    // appending after a truncation labels the new segment, not a stale one
    t.append(states_[3], {PrimitiveKind::Transfer, 3});
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t.label(1), (SegmentLabel{PrimitiveKind::Transfer, 3}));
    t.truncate(0);
    EXPECT_TRUE(t.empty());
    t.truncate(0);
    EXPECT_TRUE(t.empty());
}

TEST_F(MobileTrajectory, TruncateBeyondTheSizeKeepsEverything)
{
    Trajectory t = make(2);
    t.truncate(5);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t.label(0), (SegmentLabel{PrimitiveKind::Push, 0}));
    t.append(states_[2], {PrimitiveKind::Push, 1});
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t.label(1), (SegmentLabel{PrimitiveKind::Push, 1}));
}

TEST_F(MobileTrajectory, MoveTransfersOwnership)
{
    Trajectory source = make(3);
    const ob::State *first = source.state(0);
    Trajectory moved(std::move(source));
    ASSERT_EQ(moved.size(), 3u);
    EXPECT_EQ(moved.state(0), first);  // the same waypoints, not copies
    EXPECT_EQ(moved.label(1), (SegmentLabel{PrimitiveKind::Push, 1}));
    EXPECT_TRUE(source.empty());  // NOLINT(bugprone-use-after-move): the moved-from state is specified
    // the moved-from trajectory can be used again
    source.reset(states_[0]);
    EXPECT_EQ(source.size(), 1u);
    EXPECT_EQ(source.space(), &space_);
}
