// Tests for PartialState.
#include "ompl_mm/base/PartialState.h"
#include "ompl_mm/geometric/ManipulationSetup.h"
#include "ompl_mm/scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
namespace ob = ompl::base;

namespace
{
    class MobilePartial : public ::testing::Test
    {
    protected:
        MobilePartial()
            : setup_(loadScene(OMPL_MM_SCENES_DIR "/mobile_blocked.xml")), space_(*setup_.manipulationSpace())
        {
            fill_ = space_.cloneState(setup_.getProblemDefinition()->getStartState(0));
            out_ = space_.allocState();
        }
        ~MobilePartial() override
        {
            space_.freeState(fill_);
            space_.freeState(out_);
        }

        /** A partial state whose every part differs from the start. */
        void moveEverything(PartialState &partial)
        {
            space_.copyState(partial.state(), fill_);
            space_.robotValues(partial.state())[0] = -0.3;
            space_.robotValues(partial.state())[1] = 0.4;
            for (unsigned int i = 0; i < space_.objectCount(); ++i)
                space_.setObjectPose(partial.state(), i, {Eigen::Vector3d(0.1 * i, -0.2 * i, 0.0), 0.5 + i});
        }

        ManipulationSetup setup_;
        const ManipulationStateSpace &space_;
        ob::State *fill_;
        ob::State *out_;
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
