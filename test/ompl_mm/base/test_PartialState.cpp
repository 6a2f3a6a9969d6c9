// Tests for PartialState.
#include "ompl_mm/base/PartialState.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    class MobilePartial : public MobileBlockedTest
    {
    protected:
        /** A partial state whose every part differs from the start. */
        void moveEverything(PartialState &partial)
        {
            space_.copyState(partial.state(), fill_);
            setRobot(space_, partial.state(), -0.3, 0.4);
            for (unsigned int i = 0; i < space_.objectCount(); ++i)
                setObject(space_, partial.state(), i, 0.1 * i, -0.2 * i, 0.0, 0.5 + i);
        }

        ob::State *fill_ = startCopy();
        ob::State *out_ = newState();
    };
}  // namespace

TEST_F(MobilePartial, NewPartialStateIsFullyDefined)
{
    PartialState partial(&space_);
    EXPECT_TRUE(partial.robotDefined());
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
        EXPECT_TRUE(partial.objectDefined(i));
    moveEverything(partial);
    partial.complete(fill_, out_);
    EXPECT_TRUE(space_.equalStates(out_, partial.state()));
}

TEST_F(MobilePartial, CompleteTakesDefinedPartsFromThePartialAndTheRestFromFill)
{
    PartialState partial(&space_);
    moveEverything(partial);
    partial.setRobotDefined(false);
    partial.setObjectDefined(1, false);
    partial.setObjectDefined(3, false);
    partial.complete(fill_, out_);
    EXPECT_EQ(space_.robotValues(out_)[0], space_.robotValues(fill_)[0]);
    EXPECT_EQ(space_.robotValues(out_)[1], space_.robotValues(fill_)[1]);
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
    {
        const ob::State *source = (i == 1 || i == 3) ? fill_ : partial.state();
        EXPECT_EQ(space_.objectPosition(out_, i), space_.objectPosition(source, i)) << i;
        EXPECT_EQ(space_.objectYaw(out_, i), space_.objectYaw(source, i)) << i;
    }
}

TEST_F(MobilePartial, RobotOnlyDefined)
{
    PartialState partial(&space_);
    moveEverything(partial);
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
        partial.setObjectDefined(i, false);
    partial.complete(fill_, out_);
    EXPECT_EQ(space_.robotValues(out_)[0], -0.3);
    EXPECT_EQ(space_.robotValues(out_)[1], 0.4);
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
        EXPECT_FALSE(space_.objectMoves(out_, fill_, i)) << i;
}

TEST_F(MobilePartial, DefineAllRestoresEveryPart)
{
    PartialState partial(&space_);
    partial.setRobotDefined(false);
    partial.setObjectDefined(2, false);
    EXPECT_FALSE(partial.robotDefined());
    EXPECT_FALSE(partial.objectDefined(2));
    EXPECT_TRUE(partial.objectDefined(1));
    partial.defineAll();
    EXPECT_TRUE(partial.robotDefined());
    EXPECT_TRUE(partial.objectDefined(2));
}

TEST_F(MobilePartial, CompleteIntoTheFillStateItself)
{
    // out may alias fill: undefined parts are then left as they are
    PartialState partial(&space_);
    moveEverything(partial);
    partial.setRobotDefined(false);
    ob::State *expected = space_.cloneState(fill_);
    partial.complete(fill_, fill_);
    EXPECT_EQ(space_.robotValues(fill_)[0], space_.robotValues(expected)[0]);
    EXPECT_EQ(space_.objectPosition(fill_, 2), space_.objectPosition(partial.state(), 2));
    space_.freeState(expected);
}
