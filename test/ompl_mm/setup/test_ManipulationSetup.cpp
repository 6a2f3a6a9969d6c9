// Tests for ManipulationSetup.
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <ompl/base/PlannerTerminationCondition.h>

#include <memory>
#include <string>
#include <vector>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    /** How many segments OMPL's motion checks split a 1 m motion of the robot's first joint into. */
    unsigned int segmentsOfAMetreLongMotion(const ManipulationSetup &setup)
    {
        const ManipulationStateSpace &space = *setup.manipulationSpace();
        ob::State *a = space.cloneState(setup.getProblemDefinition()->getStartState(0));
        ob::State *b = space.cloneState(a);
        space.robotValues(b)[0] -= 1.0;
        const unsigned int count = space.validSegmentCount(a, b);
        space.freeState(a);
        space.freeState(b);
        return count;
    }
}  // namespace

TEST(ManipulationSetup, BuildsMobileBlocked)
{
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    ASSERT_TRUE(setup.model());
    EXPECT_EQ(setup.model()->objectCount(), 4u);
    EXPECT_EQ(setup.model()->dof(), 2u);
    EXPECT_EQ(setup.getStateSpace(), setup.manipulationSpace());
    EXPECT_EQ(setup.getStateValidityChecker(), setup.validityChecker());
    EXPECT_EQ(setup.getGoal(), setup.manipulationGoal());
    EXPECT_EQ(setup.getPlanner(), setup.mopl());
    ASSERT_EQ(setup.mopl()->getPrimitives().size(), 2u);
    EXPECT_EQ(setup.mopl()->getPrimitives()[0]->name(), "transit");
    const auto push = std::dynamic_pointer_cast<PushMobile>(setup.mopl()->getPrimitives()[1]);
    ASSERT_TRUE(push);
    EXPECT_DOUBLE_EQ(push->standoff(0), 0.41);
}

TEST(ManipulationSetup, StartStateIsTheScenes)
{
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    ASSERT_EQ(setup.getProblemDefinition()->getStartStateCount(), 1u);
    const ob::State *start = setup.getProblemDefinition()->getStartState(0);
    const ManipulationStateSpace &space = *setup.manipulationSpace();
    EXPECT_EQ(space.robotValues(start)[0], scene.robotStart[0]);
    EXPECT_EQ(space.robotValues(start)[1], scene.robotStart[1]);
    for (unsigned int i = 0; i < 4; ++i)
    {
        EXPECT_EQ(space.objectPosition(start, i), scene.objects[i].start.position) << i;
        EXPECT_EQ(space.objectYaw(start, i), scene.objects[i].start.yaw) << i;
    }
    EXPECT_TRUE(setup.validityChecker()->isValid(start));
    EXPECT_FALSE(setup.manipulationGoal()->isSatisfied(start));
}

TEST(ManipulationSetup, PlannerParametersAreApplied)
{
    ManipulationSetup setup(mobileBlockedScene());
    EXPECT_DOUBLE_EQ(setup.mopl()->getConnectStep(), 0.05);
    EXPECT_DOUBLE_EQ(setup.mopl()->getVertexStep(), 0.35);
    EXPECT_DOUBLE_EQ(setup.mopl()->metricWeights().movingObjectPenalty, 0.6);
    EXPECT_DOUBLE_EQ(setup.mopl()->metricWeights().moveToObjectPenalty, 0.1);
    EXPECT_DOUBLE_EQ(setup.mopl()->metricWeights().moveToObjectFactor, 1.0);

    // the connect step is the segment resolution: 20 steps for a 1 m robot motion
    setup.setup();
    EXPECT_NEAR(segmentsOfAMetreLongMotion(setup), 1.0 / 0.05, 1.0);
}

TEST(ManipulationSetup, ConnectStepSetLaterIsTheCollisionResolution)
{
    ManipulationSetup setup(mobileBlockedScene());
    setup.setup();
    // after setup, through the declared parameter as a user or a cfg file would
    ASSERT_TRUE(setup.getPlanner()->params().setParam("connect_step", "0.01"));
    EXPECT_NEAR(segmentsOfAMetreLongMotion(setup), 1.0 / 0.01, 1.0);
}

TEST(ManipulationSetup, PlansAfterTheSceneIsGone)
{
    std::unique_ptr<ManipulationSetup> setup;
    {
        const Scene scene = mobileBlockedScene();
        setup = std::make_unique<ManipulationSetup>(scene);
    }
    setup->mopl()->setSeed(1);
    setup->solve(ob::plannerOrTerminationCondition(
        ob::timedPlannerTerminationCondition(60.0),
        ob::exactSolnPlannerTerminationCondition(setup->getProblemDefinition())));
    ASSERT_TRUE(setup->getProblemDefinition()->hasExactSolution());
    EXPECT_TRUE(setup->manipulationPath().check());
    EXPECT_EQ(setup->model()->scene().name, "mobile_blocked");
}

TEST(ManipulationSetup, PlannerRegistryNamesItsPlannersAndRejectsUnknownNames)
{
    EXPECT_EQ(ManipulationSetup::plannerRegistry().names(),
              (std::vector<std::string>{"mopl", "rrtconnect", "rrt", "est"}));
    ManipulationSetup setup(mobileBlockedScene());
    const std::string message = inputErrorOf([&] { setup.setPlannerByName("prm"); });
    EXPECT_NE(message.find("unknown planner 'prm' (known: mopl, rrtconnect, rrt, est)"), std::string::npos)
        << message;
}

TEST(ManipulationSetupInput, UnknownSceneParameterNamesItsLine)
{
    Scene scene = mobileBlockedScene();
    scene.plannerParams.push_back({"no_such_parameter", "1", {"scene.xml", 42}});
    const std::string message = setupError(scene);
    EXPECT_EQ(
        message.rfind("scene.xml:42: unknown parameter 'no_such_parameter' of planner MOPL (known: ", 0), 0u)
        << message;
}

TEST(ManipulationSetupInput, BadSceneParameterValueNamesItsLineAndRange)
{
    Scene scene = mobileBlockedScene();
    scene.plannerParams.push_back({"object_sample_probability", "1.5", {"scene.xml", 7}});
    const std::string message = setupError(scene);
    EXPECT_EQ(
        message.rfind(
            "scene.xml:7: bad value '1.5' for parameter 'object_sample_probability' of planner MOPL", 0),
        0u)
        << message;
    EXPECT_NE(message.find("range 0.:0.05:1."), std::string::npos) << message;
}

TEST(ManipulationSetup, NoSolutionBeforeSolving)
{
    ManipulationSetup setup(mobileBlockedScene());
    EXPECT_THROW(setup.manipulationPath(), ompl::Exception);
}

TEST(ManipulationSetupInput, StartJointCountIsReportedAtTheStartLine)
{
    Scene scene = mobileBlockedScene();
    ASSERT_GT(scene.robotStartWhere.line, 0);
    scene.robotStart = {1.9};
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.robotStartWhere.str() + ": ")) << what;
    EXPECT_TRUE(contains(what, "1 joint values")) << what;
    EXPECT_TRUE(contains(what, "2 moving joints")) << what;
}

TEST(ManipulationSetup, AFixedJointIsNoPlanningJointAndHoldsItsValue)
{
    // MOBILE BLOCKED's world with the base's y held where it starts: the robot transits along x
    // alone (a push needs both base joints)
    Scene scene = mobileBlockedScene();
    const double y = scene.robotStart[1];
    scene.robot.fixedJoints.push_back({"y", y, ompl_core::SourceLocation{"s.xml", 3}});
    scene.robotStart = {scene.robotStart[0]};
    scene.robotGoal.joints.resize(1);
    scene.objectGoals.clear();
    scene.primitives = {{"transit", {}, {}}};
    ManipulationSetup setup(scene);
    const ManipulationModel &model = *setup.manipulationSpace()->model();
    ASSERT_EQ(model.dof(), 1u);
    EXPECT_EQ(model.robot().variableNames(), "x");
    EXPECT_EQ(setup.getStateSpace()->getDimension(), 1u + 4u * model.objectCount());
    const double q[] = {0.25};
    const Eigen::Vector3d body =
        model.robot().linkFrame(q, scene.robot.basePose, model.robot().linkIndex("body")).translation() -
        scene.robot.basePose.translation();
    EXPECT_NEAR(body.x(), 0.25, 1e-12);
    EXPECT_NEAR(body.y(), y, 1e-12);
}

TEST(ManipulationSetupInput, FixedJointFaultsAreReportedAtTheirLine)
{
    Scene scene = mobileBlockedScene();
    scene.robot.fixedJoints.push_back({"z", 0.0, ompl_core::SourceLocation{"s.xml", 3}});
    EXPECT_EQ(setupError(scene),
              "s.xml:3: robot 'mobile_disc' has no moving joint 'z' (its moving joints: x, y)");
    scene.robot.fixedJoints.back() = {"y", 3.0, ompl_core::SourceLocation{"s.xml", 4}};
    EXPECT_EQ(setupError(scene), "s.xml:4: joint 'y': value 3 lies outside its limits [-2.5, 2.5]");
    // the start still lists both joints: its count error names the one left to plan
    scene.robot.fixedJoints.back().value = 0.0;
    const std::string what = setupError(scene);
    EXPECT_TRUE(contains(what, "start has 2 joint values but robot 'mobile_disc' has 1 moving joints (x)"))
        << what;
}

TEST(ManipulationSetupInput, StartInCollisionNamesTheBodies)
{
    Scene scene = mobileBlockedScene();
    scene.robotStart = {-1.0, 0.0};  // inside block1
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.robotStartWhere.str() + ": ")) << what;
    EXPECT_TRUE(contains(what, "block1")) << what;
    EXPECT_TRUE(contains(what, "robot link 'body'")) << what;

    scene = mobileBlockedScene();
    scene.objects[3].start.position = Eigen::Vector3d(1.9, 1.7, 0.0);  // obj4 under the robot
    EXPECT_EQ(setupError(scene),
              scene.objects[3].where.str() +
                  ": the start state is invalid: robot link 'body' and object 'obj4' collide");
}

TEST(ManipulationSetupInput, StartJointOutsideLimitsIsReported)
{
    Scene scene = mobileBlockedScene();
    scene.robotStart = {1.9, 2.7};
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.robotStartWhere.str() + ": ")) << what;
    EXPECT_TRUE(contains(what, "'y'")) << what;
}

TEST(ManipulationSetupInput, ObjectStartOffEverySurfaceIsReportedAtTheObject)
{
    for (const Eigen::Vector3d &position :
         {Eigen::Vector3d(0.8, -0.1, 0.3), Eigen::Vector3d(0.8, -0.1, -0.01)})
    {
        Scene scene = mobileBlockedScene();
        scene.objects[1].start.position = position;
        const std::string what = setupError(scene);
        EXPECT_TRUE(startsWith(what, scene.objects[1].where.str() + ": ")) << what;
        EXPECT_TRUE(contains(what, "'obj2'")) << what;
        EXPECT_TRUE(contains(what, "no support surface")) << what;
    }
}

TEST(ManipulationSetupInput, UnknownPlannerParameterIsNamed)
{
    Scene scene = mobileBlockedScene();
    scene.plannerParams.push_back({"warp_speed", "9", {"unit_params.xml", 42}});
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, "unit_params.xml:42: ")) << what;
    EXPECT_TRUE(contains(what, "'warp_speed'")) << what;
    EXPECT_TRUE(contains(what, "connect_step")) << what;  // the known names are listed
}

TEST(ManipulationSetupInput, BadPlannerParameterValueIsNamed)
{
    const std::vector<std::pair<std::string, std::string>> bad{{"connect_step", "abc"},
                                                               {"connect_step", "-1"},
                                                               {"vertex_step", "0"},
                                                               {"undefined_probability", "1.5"}};
    for (const auto &[name, value] : bad)
    {
        Scene scene = mobileBlockedScene();
        scene.plannerParams.push_back({name, value, {"unit_params.xml", 7}});
        const std::string what = setupError(scene);
        EXPECT_TRUE(startsWith(what, "unit_params.xml:7: ")) << name << "=" << value << ": " << what;
        EXPECT_TRUE(contains(what, "'" + name + "'")) << what;
        EXPECT_TRUE(contains(what, "'" + value + "'")) << what;
    }
}

TEST(ManipulationSetupInput, UnknownPrimitiveTypeIsReportedAtItsLine)
{
    Scene scene = mobileBlockedScene();
    scene.primitives.push_back({"teleport", {}, {"unit_prims.xml", 9}});
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, "unit_prims.xml:9: ")) << what;
    EXPECT_TRUE(contains(what, "teleport")) << what;
}

TEST(ManipulationSetupInput, OnlyTheMoplPlannerIsKnown)
{
    Scene scene = mobileBlockedScene();
    scene.planner = "rrt_connect";
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.file)) << what;
    EXPECT_TRUE(contains(what, "rrt_connect")) << what;
    EXPECT_TRUE(contains(what, "mopl")) << what;
}

TEST(ManipulationSetupInput, RobotFaultsAreReportedAtTheRobotLine)
{
    Scene scene = mobileBlockedScene();
    ASSERT_GT(scene.robot.where.line, 0);
    scene.robot.toolLink = "gripper";
    std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.robot.where.str() + ": ")) << what;
    EXPECT_TRUE(contains(what, "gripper")) << what;

    scene = mobileBlockedScene();
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/unit_no_such_robot.urdf";
    what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.robot.where.str() + ": ")) << what;
    EXPECT_TRUE(contains(what, "unit_no_such_robot.urdf")) << what;
}

TEST(ManipulationSetupInput, StartJointOutsideLimitsNamesTheValueAndTheLimits)
{
    // the start state's check reports the joint, its value and its limits, at the start line
    Scene scene = mobileBlockedScene();
    scene.robotStart = {-2.6, 1.9};
    const std::string what = setupError(scene);
    EXPECT_EQ(what,
              scene.robotStartWhere.str() +
                  ": the start state is invalid: joint 'x' = -2.600000 is outside [-2.500000, 2.500000]");
}

TEST(ManipulationSetupInput, MalformedUrdfIsReportedAtTheRobotLineWithTheUrdfsOwnPlace)
{
    // a URDF fault carries the URDF's file:line after the scene's robot line
    Scene scene = mobileBlockedScene();
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/bad_mesh.urdf";
    const std::string what = setupError(scene);
    EXPECT_TRUE(startsWith(what, scene.robot.where.str() + ": " + scene.robot.urdfFile + ":5: ")) << what;
    EXPECT_TRUE(contains(what, "mesh 'arm.stl' not found")) << what;
}

TEST(ManipulationSetupInput, ARobotWithoutCollisionGeometryIsRejectedAtTheRobotLine)
{
    // a kinematic model (no <collision> anywhere) would plan through every obstacle
    Scene scene = mobileBlockedScene();
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/kuka_lwr_dh.urdf";
    EXPECT_EQ(setupError(scene),
              scene.robot.where.str() + ": robot 'kuka_lwr_dh' (" + scene.robot.urdfFile +
                  ") has no collision geometry on any link: it would pass through everything");
}

TEST(ManipulationSetupInput, ObjectStartJustWithinTheRestToleranceIsAccepted)
{
    // 1e-4 is the rest tolerance: 0.9e-4 above the floor rests, 1.1e-4 does not
    Scene scene = mobileBlockedScene();
    scene.objects[1].start.position.z() = 0.9e-4;
    EXPECT_EQ(setupError(scene), "");
    scene.objects[1].start.position.z() = 1.1e-4;
    EXPECT_EQ(setupError(scene),
              scene.objects[1].where.str() + ": object 'obj2' starts on no support surface");
}

TEST(ManipulationSetupInput, AllowedCollisionWithAnUnknownLinkIsNamed)
{
    // an <allow_collision> pair must name links of the robot
    Scene scene = mobileBlockedScene();
    scene.robot.allowedCollisions.push_back({"body", "gripper", ompl_core::SourceLocation{"s.xml", 12}});
    EXPECT_EQ(setupError(scene),
              "s.xml:12: allow_collision names link 'gripper', which robot 'mobile_disc' does not have");
}

TEST(ManipulationSetup, SegmentResolutionLongerThanAnObjectsYawRangeIsAccepted)
{
    // the yaw subspace spans 2 pi: a resolution of 7 checks it once per motion instead of throwing
    // half-set (connect_step stops at 1, but a subspace may be shorter than that)
    ManipulationSetup setup(mobileBlockedScene());
    ASSERT_TRUE(setup.getPlanner()->params().setParam("connect_step", "0.5"));
    EXPECT_TRUE(setup.getPlanner()->params().setParam("connect_step", "1"));
    EXPECT_EQ(setup.mopl()->getConnectStep(), 1.0);
    setup.manipulationSpace()->setSegmentResolution(7.0);
    EXPECT_NEAR(segmentsOfAMetreLongMotion(setup), 1.0, 1.0);
}

TEST(ManipulationSetupInput, AToolFrameOnAnUnknownLinkIsNamedAtItsLine)
{
    Scene scene = mobileBlockedScene();
    scene.robot.tools.push_back(
        {"grasp", "hand", Eigen::Isometry3d::Identity(), ompl_core::SourceLocation{"s.xml", 14}});
    EXPECT_EQ(setupError(scene),
              "s.xml:14: tool frame 'grasp' names link 'hand', which robot 'mobile_disc' does not have");
}

TEST(ManipulationSetup, TheToolFrameIsTheToolLinksFrameTimesTheToolOffset)
{
    // a tool offset with a turn: the tool point's frame turns with it, and so does its chain
    Scene scene = mobileBlockedScene();
    scene.robot.toolOffset =
        Eigen::Translation3d(0, 0, 0.2) * Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY());
    ManipulationSetup setup(scene);
    const ManipulationModel &model = *setup.manipulationSpace()->model();
    const std::vector<double> q{0.7, -1.1};
    const Eigen::Isometry3d expected =
        model.robot().linkFrame(q.data(), scene.robot.basePose, model.toolLink()) * scene.robot.toolOffset;
    EXPECT_TRUE(model.toolFrame(q.data()).isApprox(expected, 1e-12));
    EXPECT_TRUE(model.toolPointChain().toolPose(q.data(), scene.robot.basePose).isApprox(expected, 1e-12));
}

TEST(ManipulationSetup, ToolFramesGiveTheirChains)
{
    // a frame 0.1 m above the body, turned about z: its chain's pose is the link's frame times it
    Scene scene = mobileBlockedScene();
    const Eigen::Isometry3d offset =
        Eigen::Translation3d(0, 0, 0.1) * Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ());
    scene.robot.tools.push_back({"top", "body", offset, ompl_core::SourceLocation{"s.xml", 14}});
    ManipulationSetup setup(scene);
    const ManipulationModel &model = *setup.manipulationSpace()->model();
    const KinematicChain &chain = model.toolChain("top");
    EXPECT_EQ(chain.size(), 2u);
    const std::vector<double> q{0.7, -1.1};
    const Eigen::Isometry3d expected =
        model.robot().linkFrame(q.data(), scene.robot.basePose, model.robot().linkIndex("body")) * offset;
    EXPECT_TRUE(chain.toolPose(q.data(), scene.robot.basePose).isApprox(expected, 1e-12));
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { model.toolChain("none"); }),
              "ManipulationModel: the scene declares no tool frame 'none'");
}

namespace
{
    Scene kukaReach()
    {
        return loadScene(OMPL_MM_SCENES_DIR "/kuka_reach.xml");
    }
}  // namespace

TEST(ManipulationSetupOmplPlanners, RrtConnectPlansATransitAndItsPathIsAManipulationPath)
{
    const Scene scene = kukaReach();
    ManipulationSetup setup(scene);
    setup.selectPlanner("rrtconnect");
    // MOPL's scene parameters are not RRTConnect's: none applied, none rejected
    EXPECT_FALSE(setup.getPlanner()->params().hasParam("connect_step"));
    ASSERT_EQ(setup.solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
    const ManipulationPath &path = setup.manipulationPath();
    EXPECT_EQ(&path, &setup.manipulationPath()) << "converted once, then kept";
    EXPECT_TRUE(path.check());
    EXPECT_GE(path.getStateCount(), 3u) << "the straight motion collides: a detour is needed";
    for (const SegmentLabel &label : path.labels())
        EXPECT_EQ(label, (SegmentLabel{PrimitiveKind::Transit, -1}));
    const ob::State *end = path.getState(path.getStateCount() - 1);
    EXPECT_TRUE(setup.getGoal()->isSatisfied(end));
    for (unsigned int i = 0; i < setup.manipulationSpace()->objectCount(); ++i)
        EXPECT_EQ(setup.manipulationSpace()->objectPosition(end, i), scene.objects[i].start.position);
    EXPECT_EQ(setup.getProblemDefinition()->getSolutions().front().plannerName_, "RRTConnect");
}

TEST(ManipulationSetupOmplPlanners, AnotherPlannerTakesTheSceneParametersItDeclares)
{
    Scene scene = kukaReach();
    scene.planner = "rrt";
    scene.plannerParams = {{"range", "0.25", {scene.file, 70}}, {"goal_bias", "0.1", {scene.file, 71}}};
    ManipulationSetup setup(scene);
    EXPECT_EQ(setup.getPlanner()->params().getParam("goal_bias")->getValue(), "0.1");
    setup.selectPlanner("rrtconnect");  // declares range, not goal_bias
    EXPECT_EQ(setup.getPlanner()->params().getParam("range")->getValue(), "0.25");
    setup.selectPlanner("mopl");  // declares neither
    EXPECT_EQ(setup.getPlanner()->getName(), "MOPL");
}

TEST(ManipulationSetupOmplPlanners, GoalSamplesKeepFreeObjectsWhereTheyStart)
{
    const Scene scene = kukaReach();
    ManipulationSetup setup(scene);
    const auto &goal = *setup.manipulationGoal();
    ob::ScopedState<> sample(setup.getStateSpace());
    for (int k = 0; k < 20; ++k)
    {
        goal.sampleGoal(sample.get());
        ASSERT_TRUE(goal.isSatisfied(sample.get()));
        for (unsigned int i = 0; i < setup.manipulationSpace()->objectCount(); ++i)
            ASSERT_EQ(setup.manipulationSpace()->objectPosition(sample.get(), i),
                      scene.objects[i].start.position);
    }
}

TEST(ManipulationSetupOmplPlanners, TheirUniformSamplesMoveTheRobotAlone)
{
    const Scene scene = kukaReach();
    ManipulationSetup setup(scene);
    setup.selectPlanner("est");
    const ob::StateSamplerPtr sampler = setup.getStateSpace()->allocStateSampler();
    ob::ScopedState<> a(setup.getStateSpace()), b(setup.getStateSpace());
    sampler->sampleUniform(a.get());
    sampler->sampleUniform(b.get());
    const auto &space = *setup.manipulationSpace();
    EXPECT_TRUE(space.robotMoves(a.get(), b.get()));
    for (unsigned int i = 0; i < space.objectCount(); ++i)
        EXPECT_EQ(space.objectPose(a.get(), i).position, scene.objects[i].start.position);
    // MOPL's setup keeps OMPL's uniform sampling of every coordinate
    ManipulationSetup moplSetup(scene);
    const ob::StateSamplerPtr all = moplSetup.getStateSpace()->allocStateSampler();
    all->sampleUniform(a.get());
    EXPECT_NE(space.objectPosition(a.get(), 0), scene.objects[0].start.position);
}
