// Tests for MotionBounds: the bounds hold for points of every link along random linear joint
// motions, and a mobile base translates its body exactly.
#include "ompl_mm/collision/MotionBounds.h"

#include "common/MobileArm.h"
#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <random>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** Random points of every link of the model's robot, along random parts of random linear joint
        motions, stay within their sweeps; returns the largest share of a bound a point used. */
    double largestSweepShare(const ManipulationModelPtr &model)
    {
        const RobotModel &robot = model->robot();
        const MotionBounds bounds(model);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const auto randomJoints = [&]
        {
            std::vector<double> q;
            for (unsigned int i = 0; i < robot.dof(); ++i)
                q.push_back(robot.variableJoint(i).lower +
                            unit(rng) * (robot.variableJoint(i).upper - robot.variableJoint(i).lower));
            return q;
        };
        const double reach = 0.3;
        double tightest = 0.0;  // largest share of the bound a point used: the bound is not loose by far
        for (int trial = 0; trial < 300; ++trial)
        {
            const std::vector<double> q1 = randomJoints(), q2 = randomJoints();
            double t1 = unit(rng), t2 = unit(rng);
            if (t1 > t2)
                std::swap(t1, t2);
            std::vector<double> a(q1.size()), b(q1.size());
            for (std::size_t j = 0; j < q1.size(); ++j)
            {
                a[j] = q1[j] + t1 * (q2[j] - q1[j]);
                b[j] = q1[j] + t2 * (q2[j] - q1[j]);
            }
            std::vector<Eigen::Isometry3d> framesA, framesB;
            robot.forwardKinematics(a.data(), Eigen::Isometry3d::Identity(), framesA);
            robot.forwardKinematics(b.data(), Eigen::Isometry3d::Identity(), framesB);
            for (std::size_t l = 0; l < robot.links().size(); ++l)
            {
                const BodySweep sweep = bounds.linkSweep(static_cast<int>(l), reach, q1.data(), q2.data());
                const Eigen::Vector3d point =
                    reach * Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
                const Eigen::Vector3d moved =
                    framesB[l] * point - framesA[l] * point - (t2 - t1) * sweep.translation;
                EXPECT_LE(moved.norm(), (t2 - t1) * sweep.spread + 1e-12) << "link " << robot.links()[l].name;
                if (sweep.spread > 0.0)
                    tightest = std::max(tightest, moved.norm() / ((t2 - t1) * sweep.spread));
            }
        }
        return tightest;
    }

    /** A model of test/data/robots/mimic_gripper.urdf: a wrist with fingers and knuckles that
        follow one leader. */
    ManipulationModelPtr mimicGripper()
    {
        Scene scene;
        scene.robot.toolLink = "hand";
        return std::make_shared<ManipulationModel>(
            scene,
            RobotModel::fromUrdfFile(std::string(OMPL_MM_TEST_DATA_DIR) + "/robots/mimic_gripper.urdf"));
    }
}  // namespace

TEST(MotionBounds, EveryPointOfEveryLinkMovesWithinItsSweep)
{
    EXPECT_GT(largestSweepShare(mobileArm()), 0.3);
}

TEST(MotionBounds, MimicJointsMoveTheirLinksWithinTheirSweeps)
{
    EXPECT_GT(largestSweepShare(mimicGripper()), 0.3);
}

TEST(MotionBounds, FingersOfOneLeaderMoveRelativeToEachOther)
{
    // the right finger follows the left one's variable, yet the two move apart: no shared joint
    const ManipulationModelPtr model = mimicGripper();
    const MotionBounds bounds(model);
    const RobotModel &robot = model->robot();
    const int left = robot.linkIndex("left_finger"), right = robot.linkIndex("right_finger");
    const std::vector<double> q1{0.3, 0.0}, q2{0.3, 0.04};
    const double rate = bounds.relativeRate(left, 0.0, right, 0.0, q1.data(), q2.data());
    std::vector<Eigen::Isometry3d> start, end;
    robot.forwardKinematics(q1.data(), Eigen::Isometry3d::Identity(), start);
    robot.forwardKinematics(q2.data(), Eigen::Isometry3d::Identity(), end);
    const double change = (end[left].translation() - end[right].translation()).norm() -
                          (start[left].translation() - start[right].translation()).norm();
    EXPECT_NEAR(change, 0.08, 1e-12);
    EXPECT_GE(rate, change);
}

TEST(MotionBounds, AMobileBaseTranslatesExactly)
{
    const ManipulationModelPtr model = mobileArm();
    const MotionBounds bounds(model);
    const std::vector<double> q1{0.5, -1.0, 0.3, 0.1, 0.2}, q2{-0.5, 1.0, 0.3, 0.1, 0.2};
    const int base = model->robot().linkIndex("base");
    const BodySweep sweep = bounds.linkSweep(base, 0.3, q1.data(), q2.data());
    EXPECT_TRUE(sweep.translation.isApprox(Eigen::Vector3d(-1.0, 2.0, 0.0)));
    EXPECT_EQ(sweep.spread, 0.0);
    // the arm on it turns nothing here either: only the base moved
    const BodySweep fore = bounds.linkSweep(model->robot().linkIndex("fore"), 0.3, q1.data(), q2.data());
    EXPECT_TRUE(fore.translation.isApprox(sweep.translation));
    EXPECT_EQ(fore.spread, 0.0);
}

TEST(MotionBounds, ASlidingObjectTurnsTheShortWay)
{
    const BodySweep sweep =
        MotionBounds::slideSweep({Eigen::Vector3d(0, 0, 0), 3.0}, {Eigen::Vector3d(1, 0, 0), -3.0}, 0.5);
    EXPECT_TRUE(sweep.translation.isApprox(Eigen::Vector3d(1, 0, 0)));
    EXPECT_NEAR(sweep.spread, (2.0 * M_PI - 6.0) * 0.5, 1e-12);
}

TEST(MotionBounds, TwoLinksChangeTheirDistanceOnlyThroughTheJointsBetweenThem)
{
    const ManipulationModelPtr model = mobileArm();
    const RobotModel &robot = model->robot();
    const MotionBounds bounds(model);
    const int upper = robot.linkIndex("upper");
    const int fore = robot.linkIndex("fore");
    const double reach = 0.3;
    // x, y, shoulder and lift move both links together: their distance cannot change
    const std::vector<double> q1{0.0, 0.0, 0.0, 0.0, 0.5};
    std::vector<double> q2{1.5, -1.0, 2.0, 0.4, 0.5};
    EXPECT_EQ(bounds.relativeRate(upper, reach, fore, reach, q1.data(), q2.data()), 0.0);
    EXPECT_GT(bounds.linkSweep(fore, reach, q1.data(), q2.data()).spread, 1.0);  // though each moves far

    // the elbow turns the forearm relative to the upper arm: points of both within reach change
    // their distance by no more than the rate, over any part of the motion
    q2[4] = -1.5;
    const double rate = bounds.relativeRate(upper, reach, fore, reach, q1.data(), q2.data());
    EXPECT_GT(rate, 0.0);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-0.5, 0.5);
    double largest = 0.0;
    for (int trial = 0; trial < 200; ++trial)
    {
        const Eigen::Vector3d pa = reach * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
        const Eigen::Vector3d pb = reach * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
        const double t = unit(rng) + 0.5;
        std::vector<double> q(q1.size());
        for (std::size_t j = 0; j < q.size(); ++j)
            q[j] = q1[j] + t * (q2[j] - q1[j]);
        std::vector<Eigen::Isometry3d> start, along;
        robot.forwardKinematics(q1.data(), Eigen::Isometry3d::Identity(), start);
        robot.forwardKinematics(q.data(), Eigen::Isometry3d::Identity(), along);
        const double before = (start[upper] * pa - start[fore] * pb).norm();
        const double after = (along[upper] * pa - along[fore] * pb).norm();
        ASSERT_LE(std::abs(after - before), t * rate + 1e-12);
        largest = std::max(largest, std::abs(after - before) / (t * rate));
    }
    EXPECT_GT(largest, 0.1);  // not loose by far
}
