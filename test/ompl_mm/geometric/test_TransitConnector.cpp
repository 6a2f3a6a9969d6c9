// Tests for TransitConnector: straight when it can, around obstacles when it must, nothing when the
// goal is walled in, the same route for the same seed.
#include "ompl_mm/geometric/TransitConnector.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    class Connector : public MobileBlockedTest
    {
    protected:
        Connector()
        {
            si_->setup();
            from_ = startCopy();
            to_ = startCopy();
        }

        /** A trajectory that starts at from_. */
        Trajectory fromStart() const
        {
            Trajectory trajectory(&space_);
            trajectory.reset(from_);
            return trajectory;
        }

        /** Checks that trajectory is a chain of valid transits from from_ to to_. */
        void expectValidTransits(const Trajectory &trajectory) const
        {
            ASSERT_GE(trajectory.size(), 2u);
            EXPECT_TRUE(space_.equalStates(trajectory.state(0), from_));
            EXPECT_TRUE(space_.equalStates(trajectory.back(), to_));
            for (std::size_t k = 0; k + 1 < trajectory.size(); ++k)
            {
                EXPECT_TRUE(trajectory.label(k) == (SegmentLabel{PrimitiveKind::Transit, -1}));
                EXPECT_TRUE(si_->checkMotion(trajectory.state(k), trajectory.state(k + 1)))
                    << "segment " << k;
            }
        }

        ob::SpaceInformationPtr si_ = setup_.getSpaceInformation();
        TransitConnector connector_{si_};
        ob::State *from_;
        ob::State *to_;
    };
}  // namespace

TEST_F(Connector, RangeIsATenthOfTheJointSpace)
{
    EXPECT_DOUBLE_EQ(connector_.range(), 0.1 * std::sqrt(5.0 * 5.0 + 5.0 * 5.0));
}

TEST_F(Connector, GoesStraightWhenItCan)
{
    setRobot(space_, from_, 0.8, -1.0);
    setRobot(space_, to_, 0.8, -2.0);
    Trajectory trajectory = fromStart();
    ompl::RNG rng(1);
    ASSERT_TRUE(connector_.connect(trajectory, to_, 100, rng));
    EXPECT_EQ(trajectory.size(), 2u);
    expectValidTransits(trajectory);
}

TEST_F(Connector, GoesAroundABlock)
{
    // the straight line from east to south-west of block2 crosses it
    setRobot(space_, from_, 0.8, -1.01);
    setRobot(space_, to_, -1.0, -2.0);
    ASSERT_FALSE(si_->checkMotion(from_, to_));
    std::vector<std::vector<double>> routes;
    for (int run = 0; run < 2; ++run)
    {
        Trajectory trajectory = fromStart();
        ompl::RNG rng(7);
        ASSERT_TRUE(connector_.connect(trajectory, to_, 2000, rng));
        expectValidTransits(trajectory);
        routes.emplace_back();
        for (std::size_t k = 0; k < trajectory.size(); ++k)
            routes.back().push_back(space_.robotValues(trajectory.state(k))[0]);
    }
    EXPECT_EQ(routes[0], routes[1]) << "the same seed gives the same route";
}

TEST_F(Connector, FailsCleanlyWhenTheTargetIsWalledIn)
{
    // the robot's start corner is closed by obj4 and block3: no transit gets there
    setRobot(space_, from_, 0.8, -1.0);
    Trajectory trajectory = fromStart();
    ompl::RNG rng(1);
    EXPECT_FALSE(connector_.connect(trajectory, to_, 300, rng));
    EXPECT_EQ(trajectory.size(), 1u);
}
