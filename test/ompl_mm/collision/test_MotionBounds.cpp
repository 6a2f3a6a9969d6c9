// Tests for MotionBounds: the bounds hold for points of every link along random linear joint
// motions, and a mobile base translates its body exactly.
#include "ompl_mm/collision/MotionBounds.h"

#include "ompl_mm/base/ManipulationStateSpace.h"
#include "ompl_mm/scene/SceneLoader.h"

#include "common/MobileArm.h"
#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <random>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** Joint values drawn uniformly within the robot's limits. */
    std::vector<double> randomPose(const RobotModel &robot, std::mt19937 &rng)
    {
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<double> q;
        for (unsigned int i = 0; i < robot.dof(); ++i)
            q.push_back(robot.variableJoint(i).lower +
                        unit(rng) * (robot.variableJoint(i).upper - robot.variableJoint(i).lower));
        return q;
    }

    /** Random points of every link of the model's robot, along random parts of random linear joint
        motions, stay within their sweeps; returns the largest share of a bound a point used. */
    double largestSweepShare(const ManipulationModelPtr &model)
    {
        const RobotModel &robot = model->robot();
        const MotionBounds bounds(model);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const auto randomJoints = [&] { return randomPose(robot, rng); };
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

namespace
{
    /** Along random parts of random linear joint motions of the model's robot, the velocity of
        every link (alone, and relative to every other link) is the derivative of its points'
        motion, and the rest of the motion stays within acceleration * h^2 / 2; returns the largest
        share of that bound a point used. */
    double largestAccelerationShare(const ManipulationModelPtr &model)
    {
        const RobotModel &robot = model->robot();
        const MotionBounds bounds(model);
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const auto randomJoints = [&] { return randomPose(robot, rng); };
        const auto framesAt = [&](const std::vector<double> &q1, const std::vector<double> &q2, double t)
        {
            std::vector<double> q(q1.size());
            for (std::size_t j = 0; j < q.size(); ++j)
                q[j] = q1[j] + t * (q2[j] - q1[j]);
            std::vector<Eigen::Isometry3d> frames;
            robot.forwardKinematics(q.data(), Eigen::Isometry3d::Identity(), frames);
            return frames;
        };
        const int links = static_cast<int>(robot.links().size());
        const double reach = 0.3;
        double tightest = 0.0;
        for (int trial = 0; trial < 200; ++trial)
        {
            const std::vector<double> q1 = randomJoints(), q2 = randomJoints();
            const double t = unit(rng), h = unit(rng) * (1.0 - t), epsilon = 1e-7;
            const std::vector<Eigen::Isometry3d> now = framesAt(q1, q2, t),
                                                 soon = framesAt(q1, q2, t + epsilon),
                                                 later = framesAt(q1, q2, t + h);
            const Eigen::Vector3d local =
                reach * unit(rng) *
                Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
            const Eigen::Vector3d other =
                reach * unit(rng) *
                Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
            for (int a = 0; a < links; ++a)
            {
                const BodyVelocity velocity = bounds.linkVelocity(a, now, q1.data(), q2.data());
                const Eigen::Vector3d pointNow = now[a] * local;
                const Eigen::Vector3d speed =
                    velocity.linear + velocity.angular.cross(pointNow - now[a].translation());
                const Eigen::Vector3d derivative = (soon[a] * local - pointNow) / epsilon;
                EXPECT_LT((derivative - speed).norm(), 1e-5 * (1.0 + speed.norm())) << robot.links()[a].name;
                const double acceleration = bounds.linkAcceleration(a, reach, q1.data(), q2.data());
                const double rest = (later[a] * local - pointNow - h * speed).norm();
                EXPECT_LE(rest, 0.5 * acceleration * h * h + 1e-12) << robot.links()[a].name;
                if (acceleration > 0.0 && h > 0.0)
                    tightest = std::max(tightest, rest / (0.5 * acceleration * h * h));
                // relative to each other link: the vector between their points, seen from their
                // common ancestor (which the joints above both move alike)
                for (int b = 0; b < links; ++b)
                {
                    if (b == a)
                        continue;
                    int ancestor = a;
                    while (!robot.isInSubtree(b, ancestor))
                        ancestor = robot.links()[ancestor].parent;
                    const auto between = [&](const std::vector<Eigen::Isometry3d> &frames) {
                        return Eigen::Vector3d(frames[ancestor].linear().transpose() *
                                               (frames[a] * local - frames[b] * other));
                    };
                    const BodyVelocity va = bounds.linkVelocity(a, now, q1.data(), q2.data(), b);
                    const BodyVelocity vb = bounds.linkVelocity(b, now, q1.data(), q2.data(), a);
                    const Eigen::Vector3d relative =
                        now[ancestor].linear().transpose() *
                        (va.linear + va.angular.cross(now[a] * local - now[a].translation()) - vb.linear -
                         vb.angular.cross(now[b] * other - now[b].translation()));
                    const Eigen::Vector3d changed = (between(soon) - between(now)) / epsilon;
                    EXPECT_LT((changed - relative).norm(), 1e-5 * (1.0 + relative.norm()))
                        << robot.links()[a].name << " from " << robot.links()[b].name;
                    const double bound = bounds.linkAcceleration(a, reach, q1.data(), q2.data(), b) +
                                         bounds.linkAcceleration(b, reach, q1.data(), q2.data(), a);
                    EXPECT_LE((between(later) - between(now) - h * relative).norm(),
                              0.5 * bound * h * h + 1e-12)
                        << robot.links()[a].name << " from " << robot.links()[b].name;
                }
            }
        }
        return tightest;
    }
}  // namespace

TEST(MotionBounds, ALinksVelocityIsItsPointsDerivativeAndItsAccelerationBoundsTheRest)
{
    EXPECT_GT(largestAccelerationShare(mobileArm()), 0.05);
    EXPECT_GT(largestAccelerationShare(mimicGripper()), 0.05);
    EXPECT_GT(largestAccelerationShare(makeModel(loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml"))), 0.05);
}

TEST(MotionBounds, AnUprightCarriedObjectMovesRelativeToALinkByTheJointsBetweenAndTheTiltAbove)
{
    // KUKA TABLE's arm carrying an upright body with the tool, its yaw kept, as the state space
    // interpolates a transfer: link and object points change their distance within the rate
    const ManipulationModelPtr model = makeModel(loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml"));
    const RobotModel &robot = model->robot();
    const MotionBounds bounds(model);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto random = [&](double size) -> Eigen::Vector3d
    { return Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * (2.0 * size); };
    const auto jointsAt = [&](const std::vector<double> &q1, const std::vector<double> &q2, double t)
    {
        std::vector<double> q(q1.size());
        for (std::size_t j = 0; j < q.size(); ++j)
            q[j] = q1[j] + t * (q2[j] - q1[j]);
        return q;
    };
    const double reach = 0.2, objectReach = 0.1, yaw = 0.7;
    double tightest = 0.0;
    for (int trial = 0; trial < 300; ++trial)
    {
        const std::vector<double> q1 = randomPose(robot, rng), q2 = randomPose(robot, rng);
        const Eigen::Vector3d grasp1 = random(0.15), grasp2 = trial % 2 ? grasp1 : random(0.15);
        const Eigen::Isometry3d tool1 = model->toolFrame(q1.data()), tool2 = model->toolFrame(q2.data());
        const ObjectPose from{tool1 * grasp1, yaw}, to{tool2 * grasp2, yaw};
        const MotionBounds::CarriedGrasp grasp =
            bounds.carriedGrasp(from, to, objectReach, q1.data(), q2.data());
        double t1 = unit(rng), t2 = unit(rng);
        if (t1 > t2)
            std::swap(t1, t2);
        std::vector<Eigen::Isometry3d> framesA, framesB;
        const std::vector<double> a = jointsAt(q1, q2, t1), b = jointsAt(q1, q2, t2);
        robot.forwardKinematics(a.data(), model->scene().robot.basePose, framesA);
        robot.forwardKinematics(b.data(), model->scene().robot.basePose, framesB);
        const ObjectPose poseA =
            ManipulationStateSpace::carriedPose(from, to, tool1, tool2, model->toolFrame(a.data()), t1, true);
        const ObjectPose poseB =
            ManipulationStateSpace::carriedPose(from, to, tool1, tool2, model->toolFrame(b.data()), t2, true);
        const Eigen::Vector3d local = random(reach / std::sqrt(3.0)),
                              offset = random(objectReach / std::sqrt(3.0));
        for (std::size_t l = 0; l < robot.links().size(); ++l)
        {
            const double rate = bounds.carriedRelativeRate(static_cast<int>(l), reach, grasp, objectReach,
                                                           q1.data(), q2.data());
            const double distanceA = (framesA[l] * local - poseA.frame() * offset).norm();
            const double distanceB = (framesB[l] * local - poseB.frame() * offset).norm();
            EXPECT_LE(std::abs(distanceB - distanceA), (t2 - t1) * rate + 1e-12) << robot.links()[l].name;
            if (rate > 0.0 && t2 > t1)
                tightest = std::max(tightest, std::abs(distanceB - distanceA) / ((t2 - t1) * rate));
        }
    }
    EXPECT_GT(tightest, 0.1);
    // the arm still, the grasp shifting: as far as the object's frame moves in the gripper
    const std::vector<double> still(robot.dof(), 0.3);
    const Eigen::Isometry3d tool = model->toolFrame(still.data());
    const MotionBounds::CarriedGrasp shifting = bounds.carriedGrasp(
        {tool * Eigen::Vector3d(0.0, 0.0, 0.05), yaw}, {tool * Eigen::Vector3d(0.1, 0.0, 0.05), yaw},
        objectReach, still.data(), still.data());
    EXPECT_NEAR(bounds.carriedRelativeRate(robot.linkIndex("link5"), reach, shifting, objectReach,
                                           still.data(), still.data()),
                0.1, 1e-12);
    // the arm swinging about its vertical first axis alone: the wrist keeps its distance to the
    // cylinder its gripper holds
    std::vector<double> q1(robot.dof(), 0.3), q2 = q1;
    q2[0] = -1.2;
    const Eigen::Vector3d inGripper(0.0, 0.0, 0.05);
    const MotionBounds::CarriedGrasp grasp = bounds.carriedGrasp(
        {model->toolFrame(q1.data()) * inGripper, yaw}, {model->toolFrame(q2.data()) * inGripper, yaw},
        objectReach, q1.data(), q2.data());
    EXPECT_NEAR(
        bounds.carriedRelativeRate(robot.linkIndex("link7"), reach, grasp, objectReach, q1.data(), q2.data()),
        0.0, 1e-12);
}
