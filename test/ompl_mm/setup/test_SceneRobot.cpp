// Tests for loadSceneRobot: the SRDF's planning group, disabled pairs, end effector and named
// states, and the scene's fixed joints, on the shipped Panda and on a closed-linkage gripper; the
// Panda's planned joints and coupled fingers as its path file shows them.
#include "ompl_mm/setup/SceneRobot.h"

#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include "common/MobileBlocked.h"
#include "common/MoplIterations.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <sstream>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    const std::string PANDA_DIR = OMPL_MM_SCENES_DIR "/robots/panda/franka_panda/";
    const std::string LINKAGE_SCENE = OMPL_MM_TEST_DATA_DIR "/scenes/linkage_gripper.xml";

    /** MOBILE BLOCKED's world with the Panda on the floor's centre, its SRDF, the arm group. */
    Scene pandaScene()
    {
        Scene scene = mobileBlockedScene();
        scene.robot.urdfFile = PANDA_DIR + "panda.urdf";
        scene.robot.srdfFile = PANDA_DIR + "panda.srdf";
        scene.robot.group = "panda_arm";
        scene.robot.toolLink = "panda_grasptarget";
        scene.robotStartState = "ready";
        scene.robotGoal = {};
        return scene;
    }

    bool hasPair(const std::vector<AllowedCollision> &pairs, const std::string &a, const std::string &b)
    {
        return std::any_of(
            pairs.begin(), pairs.end(),
            [&](const AllowedCollision &pair)
            { return (pair.link1 == a && pair.link2 == b) || (pair.link1 == b && pair.link2 == a); });
    }
}  // namespace

TEST(SceneRobot, ThePandasArmGroupPlansSevenJointsWithTheHandHeld)
{
    const SceneRobot loaded = loadSceneRobot(pandaScene());
    EXPECT_EQ(
        loaded.robot.variableNames(),
        "panda_joint1, panda_joint2, panda_joint3, panda_joint4, panda_joint5, panda_joint6, panda_joint7");
    EXPECT_EQ(loaded.scene.robotStart, (std::vector<double>{0, -0.785, 0, -2.356, 0, 1.571, 0.785}));
    // the hand is the arm's end effector: its links may touch what it holds
    EXPECT_EQ(loaded.scene.robot.gripperLinks,
              (std::vector<std::string>{"panda_hand", "panda_leftfinger", "panda_rightfinger"}));
    ASSERT_TRUE(hasPair(loaded.scene.robot.allowedCollisions, "panda_leftfinger", "panda_rightfinger"));
    for (const AllowedCollision &pair : loaded.scene.robot.allowedCollisions)
        EXPECT_EQ(pair.where.file, PANDA_DIR + "panda.srdf");
    // the fingers, outside the group, are held closed (0 lies within their limits)
    const RobotModel full = RobotModel::fromUrdfFile(PANDA_DIR + "panda.urdf");
    std::vector<double> q(full.dof(), 0.0), held(loaded.robot.dof(), 0.0);
    std::vector<Eigen::Isometry3d> framesFull, framesHeld;
    full.forwardKinematics(q.data(), Eigen::Isometry3d::Identity(), framesFull);
    loaded.robot.forwardKinematics(held.data(), Eigen::Isometry3d::Identity(), framesHeld);
    const int finger = full.linkIndex("panda_rightfinger");
    EXPECT_TRUE(framesFull[finger].isApprox(framesHeld[finger], 1e-12));
}

TEST(SceneRobot, AFixedJointOutsideTheGroupKeepsItsValue)
{
    Scene scene = pandaScene();
    scene.robot.fixedJoints.push_back({"panda_finger_joint1", 0.04, ompl_core::SourceLocation{"s.xml", 5}});
    const SceneRobot loaded = loadSceneRobot(scene);
    ASSERT_EQ(loaded.robot.dof(), 7u);
    const RobotModel full = RobotModel::fromUrdfFile(PANDA_DIR + "panda.urdf");
    std::vector<double> q(full.dof(), 0.0), held(7, 0.0);
    q[7] = 0.04;  // the leader; its mimic follows
    std::vector<Eigen::Isometry3d> framesFull, framesHeld;
    full.forwardKinematics(q.data(), Eigen::Isometry3d::Identity(), framesFull);
    loaded.robot.forwardKinematics(held.data(), Eigen::Isometry3d::Identity(), framesHeld);
    for (const char *link : {"panda_leftfinger", "panda_rightfinger"})
        EXPECT_TRUE(framesFull[full.linkIndex(link)].isApprox(framesHeld[full.linkIndex(link)], 1e-12))
            << link;
}

TEST(SceneRobot, SrdfFaultsNameTheirPlace)
{
    Scene scene = pandaScene();
    scene.robot.where = {"s.xml", 3};
    scene.robot.group = "arm";
    EXPECT_EQ(inputErrorOf([&] { loadSceneRobot(scene); }),
              "s.xml:3: SRDF file '" + PANDA_DIR + "panda.srdf' has no group 'arm'");
    scene.robot.group = "";
    scene.robotStartWhere = {"s.xml", 12};
    const std::string message = inputErrorOf([&] { loadSceneRobot(scene); });
    EXPECT_EQ(message.rfind("s.xml:12: state 'ready' of group 'panda_arm' (" + PANDA_DIR +
                                "panda.srdf:20) gives no value for planning joint 'panda_finger_joint1'",
                            0),
              0u)
        << message;
    scene.robot.group = "panda_arm";
    scene.robotStartState = "home";
    EXPECT_EQ(inputErrorOf([&] { loadSceneRobot(scene); }),
              "s.xml:12: SRDF file '" + PANDA_DIR + "panda.srdf' has no group state 'home'");
    scene.robot.srdfFile.clear();
    scene.robot.group.clear();
    EXPECT_EQ(inputErrorOf([&] { loadSceneRobot(scene); }),
              "s.xml:12: a named state needs the robot's SRDF file (RobotSpec::srdfFile)");
}

TEST(SceneRobot, SrdfPairsStandInForAllowCollisionOnAClosedLinkage)
{
    // the finger and the knuckle overlap at the start: the SRDF's pair lets the setup through
    const Scene scene = loadScene(LINKAGE_SCENE);
    ManipulationSetup setup(scene);
    EXPECT_EQ(setup.manipulationSpace()->model()->dof(), 2u);
    EXPECT_EQ(setup.solve(5.0), ompl::base::PlannerStatus::EXACT_SOLUTION);

    // without the SRDF, the same robot collides with itself where it starts
    Scene plain = scene;
    plain.robot.srdfFile.clear();
    plain.robot.group.clear();
    plain.robotStartState.clear();
    plain.robotGoal.state.clear();
    plain.robotStart = {0.0, 0.0};
    plain.robotGoal.joints = {0.15, 0.0};
    const std::string message = setupError(plain);
    EXPECT_NE(message.find("robot link 'finger' and robot link 'knuckle' collide"), std::string::npos)
        << message;
}

namespace
{
    /** The path file of a solved setup: its header's column names and its rows of numbers (the
        segment and object columns left out). */
    std::pair<std::vector<std::string>, std::vector<std::vector<double>>> pathFileOf(
        const ManipulationSetup &setup)
    {
        std::ostringstream out;
        writePathFile(out, setup.manipulationPath());
        std::istringstream in(out.str());
        std::string line;
        std::getline(in, line);
        std::istringstream header(line.substr(2));
        std::vector<std::string> columns{std::istream_iterator<std::string>(header), {}};
        std::vector<std::vector<double>> rows;
        while (std::getline(in, line))
        {
            std::istringstream fields(line);
            std::string segment, object;
            fields >> segment >> object;
            rows.emplace_back(std::istream_iterator<double>(fields), std::istream_iterator<double>());
        }
        return {columns, rows};
    }
}  // namespace

TEST(SceneRobot, ThePandaPlansSevenJointsOrItsFingersCoupledAsThePathFileShows)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // the arm group: 7 joint columns, no finger
    Scene arm = loadScene(OMPL_MM_SCENES_DIR "/panda_reach.xml");
    ManipulationSetup armSetup(arm);
    armSetup.mopl()->setSeed(1);
    ASSERT_EQ(armSetup.solve(test::moplIterations(armSetup, 2000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    const auto [armColumns, armRows] = pathFileOf(armSetup);
    EXPECT_EQ(std::count_if(armColumns.begin(), armColumns.end(),
                            [](const std::string &c) { return c.rfind("panda_joint", 0) == 0; }),
              7);
    EXPECT_EQ(std::find(armColumns.begin(), armColumns.end(), "panda_finger_joint1"), armColumns.end());

    // arm and hand: the first finger planned, the second following it in every row
    Scene hand = arm;
    hand.robot.group = "panda_arm_hand";
    hand.robot.fixedJoints.clear();
    hand.robotStart.push_back(0.04);
    hand.robotGoal.joints.push_back(0.01);
    ManipulationSetup handSetup(hand);
    EXPECT_EQ(handSetup.manipulationSpace()->model()->dof(), 8u);
    handSetup.mopl()->setSeed(1);
    ASSERT_EQ(handSetup.solve(test::moplIterations(handSetup, 2000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    const auto [columns, rows] = pathFileOf(handSetup);
    const auto column = [&columns = columns](const std::string &name) {
        return std::find(columns.begin(), columns.end(), name) - columns.begin() - 2;
    };  // less segment, object
    const long leader = column("panda_finger_joint1"), follower = column("panda_finger_joint2");
    ASSERT_LT(leader, static_cast<long>(columns.size()) - 2);
    ASSERT_LT(follower, static_cast<long>(columns.size()) - 2);
    ASSERT_GT(rows.size(), 1u);
    for (const std::vector<double> &row : rows)
        EXPECT_EQ(row[follower], row[leader]);
    EXPECT_NEAR(rows.front()[leader], 0.04, 1e-12);
    EXPECT_NEAR(rows.back()[leader], 0.01, 0.01);
}
