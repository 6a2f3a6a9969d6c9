#include "ompl_mmphys/simulation/MotionExecution.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** Counts the world steps of an execution. */
    class StepCounter : public ompl_mmphys::ExecutionObserver
    {
    public:
        void stepped(const double *) override { ++steps; }
        std::size_t steps{0};
    };

    /** MOBILE BLOCKED's ODE world at the start, obj1 raised by `drop` metres above its surface. */
    class SettlingTest : public MobileBlockedTest
    {
    protected:
        /** Settles the world for settings' settleTime (or less) and returns the steps it took. */
        std::size_t settle(double drop)
        {
            const ompl::base::State *start = startCopy();
            std::vector<ObjectPose> poses = ompl_mmphys::objectPoses(space_, start);
            poses[0].position.z() += drop;
            world_ = std::make_unique<ompl_mmphys::PlanWorld>(space_.model(), space_.robotValues(start),
                                                              poses, settings_.world);
            ompl_mmphys::MotionExecution execution(*world_, settings_);
            StepCounter counter;
            execution.settle(space_.robotValues(start), counter);
            return counter.steps;
        }

        ompl_mmphys::SimulationSettings settings_;
        std::unique_ptr<ompl_mmphys::PlanWorld> world_;
    };
}  // namespace

TEST_F(SettlingTest, AWorldAtRestSettlesInAFewSteps)
{
    const std::size_t steps = settle(0.0);
    EXPECT_GE(steps, 10u) << "rest is seen over several steps, not one";
    EXPECT_LT(steps, 50u) << "not the whole settleTime (125 steps)";
}

TEST_F(SettlingTest, AFallingObjectIsWaitedFor)
{
    // 5 cm take 0.1 s (25 steps) to fall; settling must not stop while obj1 moves
    const std::size_t steps = settle(0.05);
    EXPECT_GT(steps, 25u);
    EXPECT_LE(steps, 125u) << "never beyond settleTime";
    const double height = space_.model()->scene().surfaces[0].height;
    EXPECT_NEAR(world_->objectPose(0).position.z(), height, ompl_mmphys::REST_SNAP)
        << "obj1 rests on the floor";
    EXPECT_LT(world_->objectSpeed(0), 1e-2);
}

TEST_F(SettlingTest, ZeroSettleTimeTakesNoStep)
{
    settings_.settleTime = 0.0;
    EXPECT_EQ(settle(0.05), 0u);
}
