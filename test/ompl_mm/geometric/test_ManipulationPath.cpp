// Tests for ManipulationPath.
#include "ompl_mm/geometric/ManipulationPath.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{

    class MobilePath : public MobileBlockedTest
    {
    protected:
        MobilePath()
        {
            si_->setup();
            state_ = startCopy();
        }

        /** state_ with the robot moved to (x, y); returns it for appending. */
        const ob::State *robotAt(double x, double y)
        {
            setRobot(space_, state_, x, y);
            return state_;
        }
        const ob::State *objectAt(unsigned int i, double x, double y)
        {
            setObject(space_, state_, i, x, y);
            return state_;
        }
        double robotX(std::size_t i) const { return space_.robotValues(path_.getState(i))[0]; }

        ob::SpaceInformationPtr si_ = setup_.getSpaceInformation();
        ManipulationPath path_{si_};
        ob::State *state_;
    };
}  // namespace

TEST_F(MobilePath, AppendFirstThenLabelled)
{
    EXPECT_THROW(path_.appendLabelled(state_, TRANSIT), ompl::Exception);
    path_.appendFirst(state_);
    EXPECT_THROW(path_.appendFirst(state_), ompl::Exception);
    path_.appendLabelled(robotAt(1.0, 1.9), TRANSIT);
    path_.appendLabelled(objectAt(3, 0.9, 1.9), pushOf(3));
    ASSERT_EQ(path_.getStateCount(), 3u);
    ASSERT_EQ(path_.labels().size(), 2u);
    EXPECT_EQ(path_.label(0), TRANSIT);
    EXPECT_EQ(path_.label(1), pushOf(3));
    EXPECT_NE(path_.getState(2), state_);  // copies
    EXPECT_TRUE(space_.equalStates(path_.getState(2), state_));
}

TEST_F(MobilePath, ReplaceSwapsStatesAndLabelsForTheTrajectorys)
{
    path_.appendFirst(robotAt(1.9, 1.9));
    for (int i = 1; i <= 5; ++i)
        path_.appendLabelled(robotAt(1.9 - 0.2 * i, 1.9), i == 5 ? pushOf(1) : TRANSIT);
    // 6 states x = 1.9 1.7 1.5 1.3 1.1 0.9, labels T T T T P; states 2..4 become 1.4 1.2
    Trajectory replacement(&space_);
    replacement.reset(path_.getState(1));
    replacement.append(robotAt(1.4, 1.9), pushOf(2));
    replacement.append(robotAt(1.2, 1.9), TRANSIT);
    replacement.append(robotAt(1.1, 1.9), pushOf(3));
    path_.replace(1, 4, replacement);
    ASSERT_EQ(path_.getStateCount(), 6u);
    const double expected[] = {1.9, 1.7, 1.4, 1.2, 1.1, 0.9};
    for (std::size_t i = 0; i < 6; ++i)
        EXPECT_NEAR(robotX(i), expected[i], 1e-12) << i;
    EXPECT_EQ(path_.labels(), (std::vector<SegmentLabel>{TRANSIT, pushOf(2), TRANSIT, pushOf(3), pushOf(1)}));
    // a two-state trajectory shortcuts; at the end the last state may change
    Trajectory end(&space_);
    end.reset(path_.getState(2));
    end.append(robotAt(0.5, 1.9), TRANSIT);
    path_.replace(2, 5, end);
    ASSERT_EQ(path_.getStateCount(), 4u);
    EXPECT_NEAR(robotX(3), 0.5, 1e-12);
    EXPECT_EQ(path_.labels(), (std::vector<SegmentLabel>{TRANSIT, pushOf(2), TRANSIT}));
    // a trajectory that does not start at state first, or indices out of order, are refused
    EXPECT_THROW(path_.replace(1, 3, end), ompl::Exception);
    EXPECT_THROW(path_.replace(2, 2, end), ompl::Exception);
    EXPECT_THROW(path_.replace(2, 4, end), ompl::Exception);
    EXPECT_EQ(path_.getStateCount(), 4u);
}

TEST_F(MobilePath, RemoveRepeatedStatesKeepsTheLabelOfTheMotion)
{
    // A A B B B C, labels l0..l4: the zero-length segments go with their labels
    path_.appendFirst(robotAt(1.9, 1.9));
    path_.appendLabelled(robotAt(1.9, 1.9), pushOf(0));
    path_.appendLabelled(robotAt(1.0, 1.9), TRANSIT);
    path_.appendLabelled(robotAt(1.0, 1.9), pushOf(2));
    path_.appendLabelled(robotAt(1.0, 1.9), pushOf(3));
    path_.appendLabelled(objectAt(1, 1.0, 0.0), pushOf(1));
    path_.removeRepeatedStates();
    ASSERT_EQ(path_.getStateCount(), 3u);
    EXPECT_EQ(path_.labels(), (std::vector<SegmentLabel>{TRANSIT, pushOf(1)}));
    EXPECT_NEAR(robotX(1), 1.0, 1e-12);
    EXPECT_EQ(path_.checkLabels(), "");
}

TEST_F(MobilePath, ToolPathLengthOfStraightAndBentPaths)
{
    path_.appendFirst(robotAt(1.9, 1.9));
    path_.appendLabelled(robotAt(0.9, 1.9), TRANSIT);
    EXPECT_NEAR(path_.toolPathLength(), 1.0, 1e-9);
    // an L: 1 m west then 0.6 m south, plus a diagonal leg back
    path_.appendLabelled(robotAt(0.9, 1.3), TRANSIT);
    EXPECT_NEAR(path_.toolPathLength(), 1.6, 1e-9);
    path_.appendLabelled(robotAt(1.9, 1.9), TRANSIT);
    EXPECT_NEAR(path_.toolPathLength(), 1.6 + std::hypot(1.0, 0.6), 1e-9);
}

TEST_F(MobilePath, ToolPathLengthOfASingleStateIsZero)
{
    EXPECT_EQ(path_.toolPathLength(), 0.0);
    path_.appendFirst(state_);
    EXPECT_EQ(path_.toolPathLength(), 0.0);
}

TEST_F(MobilePath, PrimitiveCountsCountRuns)
{
    path_.appendFirst(state_);
    const std::vector<SegmentLabel> labels{TRANSIT, TRANSIT,   pushOf(1), pushOf(1),
                                           TRANSIT, pushOf(3), pushOf(1), TRANSIT};
    double x = 1.9;
    for (const SegmentLabel &label : labels)
        path_.appendLabelled(robotAt(x -= 0.1, 1.9), label);
    const auto counts = path_.primitiveCounts();
    EXPECT_EQ(counts.at("transit"), 3u);
    EXPECT_EQ(counts.at("push"), 3u);  // pushOf(1) twice, then pushOf(3), then pushOf(1) again
    EXPECT_EQ(counts.at("pickup"), 0u);
    EXPECT_EQ(counts.at("transfer"), 0u);
    EXPECT_EQ(counts.size(), 4u);
}

TEST_F(MobilePath, CheckLabelsFindsObjectsMovedOutsideTheirPush)
{
    path_.appendFirst(state_);
    path_.appendLabelled(robotAt(1.0, 1.9), TRANSIT);
    path_.appendLabelled(objectAt(1, 1.0, 0.0), pushOf(1));
    EXPECT_EQ(path_.checkLabels(), "");

    path_.appendLabelled(objectAt(1, 1.2, 0.0), TRANSIT);  // segment 2 moves obj2 under a transit
    const std::string fault = path_.checkLabels();
    EXPECT_NE(fault.find("segment 2"), std::string::npos) << fault;
    EXPECT_NE(fault.find("transit"), std::string::npos) << fault;
    EXPECT_NE(fault.find("'obj2'"), std::string::npos) << fault;
}

TEST_F(MobilePath, CheckLabelsFindsAPushOfTheWrongObject)
{
    path_.appendFirst(state_);
    path_.appendLabelled(objectAt(3, 0.9, 1.9), pushOf(1));  // obj4 moves under a push of obj2
    const std::string fault = path_.checkLabels();
    EXPECT_NE(fault.find("segment 0"), std::string::npos) << fault;
    EXPECT_NE(fault.find("'obj4'"), std::string::npos) << fault;
}
