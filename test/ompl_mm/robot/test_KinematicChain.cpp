// Tests for KinematicChain on the KUKA LWR-like arm: the tool pose equals the MOPL paper's DH table
// computed by hand at three configurations and RobotModel's forward kinematics everywhere; the geometric
// Jacobian equals finite differences of the pose; prismatic chains work as well; a turn about each
// coordinate axis and its negative matches a rotation matrix.
#include "ompl_mm/robot/KinematicChain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace ompl_mm;

namespace
{
    const double PI = std::acos(-1.0);
    const std::string KUKA = std::string(OMPL_MM_SCENES_DIR) + "/robots/kuka_lwr.urdf";
    const std::string MOBILE = std::string(OMPL_MM_SCENES_DIR) + "/robots/mobile_disc.urdf";

    /** The paper's DH table (a = 0, theta offset 0), the tool 0.285 m past the flange along its z. */
    Eigen::Isometry3d dhToolPose(const std::vector<double> &q)
    {
        const double d[] = {0.31, 0.0, 0.40, 0.0, 0.39, 0.0, 0.0};
        const double alpha[] = {90, -90, -90, 90, 90, -90, 0};
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        for (int i = 0; i < 7; ++i)
            pose = pose * Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ()) *
                   Eigen::Translation3d(0, 0, d[i]) *
                   Eigen::AngleAxisd(alpha[i] * PI / 180, Eigen::Vector3d::UnitX());
        return pose * Eigen::Translation3d(0, 0, 0.285);
    }

    double maxDifference(const Eigen::Isometry3d &a, const Eigen::Isometry3d &b)
    {
        return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
    }

    std::vector<double> randomJoints(const KinematicChain &chain, unsigned int dof, std::mt19937 &rng)
    {
        std::vector<double> q(dof, 0.0);
        for (unsigned int i = 0; i < chain.size(); ++i)
            q[chain.variable(i)] =
                std::uniform_real_distribution<double>(chain.lower(i), chain.upper(i))(rng);
        return q;
    }
}  // namespace

TEST(KinematicChain, LwrToolPoseEqualsTheDhTableAtThreeConfigurations)
{
    const RobotModel robot = RobotModel::fromUrdfFile(KUKA);
    const KinematicChain chain(robot, robot.linkIndex("tool"));
    ASSERT_EQ(chain.size(), 7u);
    const std::vector<std::vector<double>> configurations = {{0, 0, 0, 0, 0, 0, 0},
                                                             {0.3, -0.5, 1.1, 1.2, -0.7, 0.4, 2.0},
                                                             {-2.9, 2.0, -1.5, -2.0, 2.9, -1.9, -2.9}};
    for (const std::vector<double> &q : configurations)
        EXPECT_LT(maxDifference(chain.toolPose(q.data(), Eigen::Isometry3d::Identity()), dhToolPose(q)),
                  1e-12);
    // straight up at zero: the tool 0.31 + 0.40 + 0.39 + 0.285 m above the base
    const Eigen::Vector3d top =
        chain.toolPose(configurations[0].data(), Eigen::Isometry3d::Identity()).translation();
    EXPECT_NEAR(top.z(), 1.385, 1e-12);
    EXPECT_NEAR(top.head<2>().norm(), 0.0, 1e-12);
}

TEST(KinematicChain, ToolPoseEqualsTheModelsForwardKinematicsWithABaseAndAToolOffset)
{
    const RobotModel robot = RobotModel::fromUrdfFile(KUKA);
    const Eigen::Isometry3d tool =
        Eigen::Translation3d(0.01, -0.02, 0.03) * Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY());
    const KinematicChain chain(robot, robot.linkIndex("link5"), tool);
    EXPECT_EQ(chain.size(), 5u) << "joints 1-5 move link 5";
    const Eigen::Isometry3d base =
        Eigen::Translation3d(0.5, -0.2, 0.1) * Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
    std::mt19937 rng(3);
    for (int k = 0; k < 50; ++k)
    {
        const std::vector<double> q = randomJoints(chain, robot.dof(), rng);
        EXPECT_LT(maxDifference(chain.toolPose(q.data(), base),
                                robot.linkFrame(q.data(), base, robot.linkIndex("link5")) * tool),
                  1e-12);
    }
}

TEST(KinematicChain, ToolPoseEqualsTheModelsForwardKinematicsForAxesOfEveryDirection)
{
    // the Meka-like arm turns about -x, -y and -z, the torso's left arm about a slanted axis (1 1 0)
    const std::vector<std::pair<std::string, std::string>> chains = {
        {std::string(OMPL_MM_SCENES_DIR) + "/robots/meka_torso_arm.urdf", "tool"},
        {std::string(OMPL_MM_TEST_DATA_DIR) + "/robots/torso_tree.urdf", "left_hand"}};
    const Eigen::Isometry3d base =
        Eigen::Translation3d(0.3, 0.1, -0.2) * Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ());
    std::mt19937 rng(5);
    for (const auto &[urdf, tip] : chains)
    {
        SCOPED_TRACE(urdf);
        const RobotModel robot = RobotModel::fromUrdfFile(urdf);
        const KinematicChain chain(robot, robot.linkIndex(tip));
        Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(6, chain.size());
        for (int k = 0; k < 50; ++k)
        {
            const std::vector<double> q = randomJoints(chain, robot.dof(), rng);
            const Eigen::Isometry3d expected = robot.linkFrame(q.data(), base, robot.linkIndex(tip));
            EXPECT_LT(maxDifference(chain.toolPose(q.data(), base), expected), 1e-12);
            EXPECT_LT(maxDifference(chain.toolPoseAndJacobian(q.data(), base, jacobian), expected), 1e-12);
        }
    }
}

TEST(KinematicChain, JacobianEqualsFiniteDifferencesOfThePose)
{
    const RobotModel robot = RobotModel::fromUrdfFile(KUKA);
    const KinematicChain chain(robot, robot.linkIndex("tool"));
    const Eigen::Isometry3d base =
        Eigen::Translation3d(0.2, 0.1, -0.3) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX());
    std::mt19937 rng(5);
    const double h = 1e-6;
    Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(6, chain.size());
    for (int k = 0; k < 20; ++k)
    {
        std::vector<double> q = randomJoints(chain, robot.dof(), rng);
        const Eigen::Isometry3d pose = chain.toolPoseAndJacobian(q.data(), base, jacobian);
        EXPECT_LT(maxDifference(pose, chain.toolPose(q.data(), base)), 1e-15);
        for (unsigned int j = 0; j < chain.size(); ++j)
        {
            std::vector<double> plus = q, minus = q;
            plus[chain.variable(j)] += h;
            minus[chain.variable(j)] -= h;
            const Eigen::Isometry3d a = chain.toolPose(plus.data(), base),
                                    b = chain.toolPose(minus.data(), base);
            const Eigen::Vector3d linear = (a.translation() - b.translation()) / (2 * h);
            const Eigen::AngleAxisd turn(a.linear() * b.linear().transpose());
            const Eigen::Vector3d angular = turn.angle() * turn.axis() / (2 * h);
            EXPECT_LT((jacobian.col(j).head<3>() - linear).norm(), 1e-7) << "joint " << j;
            EXPECT_LT((jacobian.col(j).tail<3>() - angular).norm(), 1e-7) << "joint " << j;
        }
    }
}

TEST(KinematicChain, PrismaticJointsMoveTheToolAlongTheirAxes)
{
    const RobotModel robot = RobotModel::fromUrdfFile(MOBILE);
    const KinematicChain chain(robot, robot.linkIndex("body"));
    ASSERT_EQ(chain.size(), 2u);
    EXPECT_TRUE(chain.prismatic(0));
    const std::vector<double> q = {0.7, -1.2};
    Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(6, 2);
    const Eigen::Isometry3d pose =
        chain.toolPoseAndJacobian(q.data(), Eigen::Isometry3d::Identity(), jacobian);
    EXPECT_LT((pose.translation() - Eigen::Vector3d(0.7, -1.2, 0.0)).norm(), 1e-15);
    Eigen::Matrix<double, 6, 2> expected = Eigen::Matrix<double, 6, 2>::Zero();
    expected(0, 0) = 1.0;
    expected(1, 1) = 1.0;
    EXPECT_EQ(jacobian, expected);
}

TEST(KinematicChain, AChainThroughAMimicJointIsRefusedNamingIt)
{
    // inverse kinematics moves each chain joint's variable on its own, which a follower cannot do
    const RobotModel robot =
        RobotModel::fromUrdfFile(std::string(OMPL_MM_TEST_DATA_DIR) + "/robots/mimic_gripper.urdf");
    std::string message;
    try
    {
        KinematicChain chain(robot, robot.linkIndex("right_finger"));
    }
    catch (const ompl::Exception &e)
    {
        message = e.what();
    }
    EXPECT_NE(message.find("passes through joint 'right_finger_joint', which follows another"),
              std::string::npos)
        << message;
    // a chain that stops above the fingers is fine, and so is the leader's own finger
    EXPECT_EQ(KinematicChain(robot, robot.linkIndex("hand")).size(), 1u);
    EXPECT_EQ(KinematicChain(robot, robot.linkIndex("left_finger")).size(), 2u);
}

TEST(KinematicChain, TurnsAboutEachAxisAndItsNegativeAsARotationMatrixDoes)
{
    // one joint about +-x, +-y, +-z, a tip off its axis: chain and model against Eigen's own rotation
    // (both use the two-column turn, so comparing them with each other alone would not catch a sign)
    const Eigen::Vector3d tip(0.3, 0.2, 0.1);
    const double angle = 0.7;
    for (int k = 0; k < 3; ++k)
        for (const double sign : {1.0, -1.0})
        {
            Eigen::Vector3d axis = Eigen::Vector3d::Zero();
            axis[k] = sign;
            const std::string urdf =
                "<robot name='one_joint'><link name='base'/><link name='arm'/><link name='tip'/>"
                "<joint name='turn' type='revolute'><parent link='base'/><child link='arm'/>"
                "<axis xyz='" +
                std::to_string(axis.x()) + " " + std::to_string(axis.y()) + " " + std::to_string(axis.z()) +
                "'/><limit lower='-3' upper='3' effort='1' velocity='1'/></joint>"
                "<joint name='fixed_tip' type='fixed'><parent link='arm'/><child link='tip'/>"
                "<origin xyz='0.3 0.2 0.1'/></joint></robot>";
            SCOPED_TRACE(urdf);
            const RobotModel robot = RobotModel::fromUrdfString(urdf, "one_joint.urdf");
            const int tipLink = robot.linkIndex("tip");
            const KinematicChain chain(robot, tipLink);
            const std::vector<double> q{angle};
            const Eigen::AngleAxisd expected(angle, axis);
            const Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
            for (const Eigen::Isometry3d &pose :
                 {chain.toolPose(q.data(), base), robot.linkFrame(q.data(), base, tipLink)})
            {
                EXPECT_LT((pose.translation() - expected * tip).norm(), 1e-12);
                EXPECT_LT((pose.linear() - expected.toRotationMatrix()).cwiseAbs().maxCoeff(), 1e-12);
            }
        }
}
