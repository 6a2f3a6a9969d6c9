// Tests for SpeedGovernor: the robot's drive applies a control as given below the speed limit and
// holds the speed at SPEED_MARGIN x the limit beyond, within the force bounds.
#include "ompl_phys/control/SpeedGovernor.h"

#include "ompl_phys/common/PhysicsTestSupport.h"

#include <gtest/gtest.h>

using namespace ompl_phys;

namespace
{
    constexpr double DT = 0.01;

    class Governor : public ::testing::Test
    {
    protected:
        Governor() : scene_(test::smallScene()), governor_(scene_) {}

        /** The speed after one step of DT under force from velocity (a free sphere). */
        double speedAfter(const Eigen::Vector2d &velocity, const Eigen::Vector2d &force) const
        {
            return (velocity + force * (DT / scene_.robot.mass)).norm();
        }

        double bound() const { return SpeedGovernor::SPEED_MARGIN * scene_.limits.maxRobotSpeed; }

        PhysicsScene scene_;
        SpeedGovernor governor_;
    };
}  // namespace

TEST_F(Governor, AppliesTheControlAsGivenBelowTheBound)
{
    const Eigen::Vector2d velocity(0.2, -0.1);
    const Eigen::Vector2d force(3.0, -4.0);
    ASSERT_LT(speedAfter(velocity, force), bound());
    EXPECT_EQ(governor_.force(force, velocity, DT), force);
    EXPECT_EQ(governor_.force(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), DT), Eigen::Vector2d::Zero());
}

TEST_F(Governor, HoldsTheSpeedAtTheBoundInTheDirectionOfTheUngovernedMotion)
{
    const double f = scene_.limits.maxForce;
    for (const Eigen::Vector2d &velocity :
         {Eigen::Vector2d(0.45, 0.0), Eigen::Vector2d(0.3, 0.3), Eigen::Vector2d(0.0, -bound())})
        for (const Eigen::Vector2d &force :
             {Eigen::Vector2d(f, 0.0), Eigen::Vector2d(f, f), Eigen::Vector2d(0.0, -f)})
        {
            SCOPED_TRACE(::testing::Message() << velocity.transpose() << " / " << force.transpose());
            const Eigen::Vector2d ungoverned = velocity + force * (DT / scene_.robot.mass);
            if (ungoverned.norm() <= bound())
                continue;
            const Eigen::Vector2d applied = governor_.force(force, velocity, DT);
            const Eigen::Vector2d next = velocity + applied * (DT / scene_.robot.mass);
            EXPECT_NEAR(next.norm(), bound(), 1e-12);
            EXPECT_NEAR(next.normalized().dot(ungoverned.normalized()), 1.0, 1e-12);
            EXPECT_LE(applied.cwiseAbs().maxCoeff(), f);
        }
}

TEST_F(Governor, BrakesWithinTheForceBoundsAboveTheLimit)
{
    // after a bounce the robot may be far over the limit: the drive brakes, but no harder than max_force
    const double f = scene_.limits.maxForce;
    const Eigen::Vector2d velocity(2.0, -2.0);
    const Eigen::Vector2d applied = governor_.force(Eigen::Vector2d::Zero(), velocity, DT);
    EXPECT_NEAR(applied.x(), -f, 1e-12);
    EXPECT_NEAR(applied.y(), f, 1e-12);
    EXPECT_LT(speedAfter(velocity, applied), velocity.norm());
}
