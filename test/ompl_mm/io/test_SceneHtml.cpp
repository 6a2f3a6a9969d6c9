// Tests for manipulationViewerPlan and writeSceneHtml on MOBILE BLOCKED: the start alone is one frame
// at the scene's start poses; a solution (MOPL, seed 1, bounded) becomes frames at a steady tool speed
// from the start state to the path's last state, in contiguous segments labelled and coloured by
// primitive; the goals and every obstacle are drawn. A Franka Panda shows its visual meshes (reduced,
// each held once) in their colours at its link frames; surfaces stand above the tops they lie on.
#include "ompl_mm/io/SceneHtml.h"

#include "common/MobileBlocked.h"
#include "common/MoplIterations.h"
#include "common/PandaPick.h"
#include "common/ViewerPlanChecks.h"
#include "ompl_mm/io/MeshReduction.h"
#include "ompl_mm/io/PlanColours.h"
#include "ompl_mm/planners/MOPL.h"
#include "ompl_mm/robot/VisualModel.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** Twice the iterations the slowest seed of test_MOPL needs: seed 1 stops at its solution, well
        before the bound (iteration counts are deterministic per seed). */
    constexpr unsigned int MAX_ITERATIONS = 20000;
    const char *const TRANSIT_COLOUR = "#1f77b4";
    const char *const PUSH_COLOUR = "#d62728";

    /** Indices of the robot's links that have collision shapes, in link order. */
    std::vector<std::size_t> shapedLinks(const ManipulationSetup &setup)
    {
        std::vector<std::size_t> links;
        const RobotModel &robot = setup.model()->robot();
        for (std::size_t l = 0; l < robot.links().size(); ++l)
            if (!robot.links()[l].shapes.empty())
                links.push_back(l);
        return links;
    }

    /** The text of a segment label as the page writes it: "transit" or "push objN". */
    std::string labelText(const Scene &scene, const SegmentLabel &label)
    {
        std::string text = primitiveKindName(label.kind);
        if (label.object >= 0)
            text += " " + scene.objects[static_cast<std::size_t>(label.object)].name;
        return text;
    }

    /** MOBILE BLOCKED solved once with MOPL, seed 1, for every test of the suite. */
    class SceneHtmlOfSolution : public ::testing::Test
    {
    protected:
        static void SetUpTestSuite()
        {
            ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
            scene_ = std::make_unique<Scene>(mobileBlockedScene());
            setup_ = std::make_unique<ManipulationSetup>(*scene_);
            setup_->mopl()->setSeed(1);
            solved_ = setup_->solve(test::moplIterations(*setup_, MAX_ITERATIONS)) ==
                      ompl::base::PlannerStatus::EXACT_SOLUTION;
            if (solved_)
                plan_ = std::make_unique<ompl_core::ViewerPlan>(
                    manipulationViewerPlan(*setup_, &setup_->manipulationPath(), "solution"));
        }
        static void TearDownTestSuite()
        {
            plan_.reset();
            setup_.reset();
            scene_.reset();
        }
        void SetUp() override { ASSERT_TRUE(solved_) << "MOPL seed 1 found no exact solution"; }

        const ManipulationStateSpace &space() const { return *setup_->manipulationSpace(); }
        const ManipulationPath &path() const { return setup_->manipulationPath(); }

        static std::unique_ptr<Scene> scene_;
        static std::unique_ptr<ManipulationSetup> setup_;
        static bool solved_;
        static std::unique_ptr<ompl_core::ViewerPlan> plan_;
    };
    std::unique_ptr<Scene> SceneHtmlOfSolution::scene_;
    std::unique_ptr<ManipulationSetup> SceneHtmlOfSolution::setup_;
    bool SceneHtmlOfSolution::solved_ = false;
    std::unique_ptr<ompl_core::ViewerPlan> SceneHtmlOfSolution::plan_;
}  // namespace

TEST(SceneHtml, WithoutAPathOneFrameAtTheStartPoses)
{
    Scene scene = mobileBlockedScene();
    scene.objects[0].start.yaw = 0.7;  // a turn, so that the rotation is checked too
    scene.objects[2].start.yaw = -2.0;
    const ManipulationSetup setup(scene);
    const ompl_core::ViewerPlan plan = manipulationViewerPlan(setup, nullptr, "start");
    EXPECT_EQ(plan.title, "start");
    ASSERT_EQ(plan.frames.size(), 1u);
    ASSERT_EQ(plan.toolPath.size(), 1u);
    EXPECT_TRUE(plan.segments.empty());

    const std::size_t links = shapedLinks(setup).size();
    ASSERT_EQ(plan.frames[0].size(), links + scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
    {
        const Eigen::Isometry3d &pose = plan.frames[0][links + i];
        const ObjectPose &start = scene.objects[i].start;
        EXPECT_TRUE(pose.translation().isApprox(start.position, 1e-12))
            << scene.objects[i].name << ": " << pose.translation().transpose();
        const Eigen::Matrix3d yaw = Eigen::AngleAxisd(start.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        EXPECT_LT((pose.linear() - yaw).norm(), 1e-12) << scene.objects[i].name;
    }
    // the robot at its start joints (1.9, 1.9): the sphere's link frame is the joints' translation
    const std::vector<std::size_t> shaped = shapedLinks(setup);
    ASSERT_EQ(shaped.size(), 1u);
    EXPECT_LT((plan.frames[0][0].translation() - Eigen::Vector3d(1.9, 1.9, 0.0)).norm(), 1e-12);
    const ompl::base::State *start = setup.getProblemDefinition()->getStartState(0);
    EXPECT_LT((plan.toolPath[0] - setup.manipulationSpace()->toolPosition(start)).norm(), 1e-12);
}

TEST(SceneHtml, WithoutAStartStateThrows)
{
    ManipulationSetup setup(mobileBlockedScene());
    setup.getProblemDefinition()->clearStartStates();
    EXPECT_THROW(manipulationViewerPlan(setup, nullptr, "none"), ompl::Exception);
}

TEST(SceneHtml, PageCarriesTheTitleAndThePlan)
{
    const ManipulationSetup setup(mobileBlockedScene());
    std::ostringstream out;
    writeSceneHtml(out, setup, nullptr, "mobile_blocked & start");
    const std::string html = out.str();
    EXPECT_TRUE(contains(html, "<title>mobile_blocked &amp; start</title>"));
    EXPECT_TRUE(contains(html, "\"name\":\"goal obj3\""));
    EXPECT_TRUE(contains(html, "\"name\":\"wall_north\""));
}

TEST_F(SceneHtmlOfSolution, MovingBodiesAreTheShapedLinksThenTheObjects)
{
    const std::vector<std::size_t> links = shapedLinks(*setup_);
    ASSERT_EQ(plan_->moving.size(), links.size() + 4);
    for (std::size_t k = 0; k < links.size(); ++k)
        EXPECT_EQ(plan_->moving[k].name, setup_->model()->robot().links()[links[k]].name);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_EQ(plan_->moving[links.size() + i].name, "obj" + std::to_string(i + 1));
}

TEST_F(SceneHtmlOfSolution, EveryFrameHasAPosePerMovingBodyAndAToolPoint)
{
    ASSERT_GE(plan_->frames.size(), path().getStateCount());
    EXPECT_EQ(plan_->toolPath.size(), plan_->frames.size());
    for (std::size_t k = 0; k < plan_->frames.size(); ++k)
        ASSERT_EQ(plan_->frames[k].size(), plan_->moving.size()) << "frame " << k;
}

TEST_F(SceneHtmlOfSolution, FirstFrameIsTheStartAndLastFrameThePathsEnd)
{
    const std::size_t links = shapedLinks(*setup_).size();
    const ompl::base::State *first = path().getState(0);
    const ompl::base::State *last = path().getState(path().getStateCount() - 1);
    for (unsigned int i = 0; i < 4; ++i)
    {
        EXPECT_LT((plan_->frames.front()[links + i].translation() - space().objectPosition(first, i)).norm(),
                  1e-12)
            << "obj" << i + 1;
        EXPECT_LT((plan_->frames.back()[links + i].translation() - space().objectPosition(last, i)).norm(),
                  1e-12)
            << "obj" << i + 1;
    }
    EXPECT_LT((plan_->toolPath.front() - space().toolPosition(first)).norm(), 1e-12);
    EXPECT_LT((plan_->toolPath.back() - space().toolPosition(last)).norm(), 1e-12);
    // obj3 ends at its goal (-0.9, -0.9) within the goal's tolerance
    EXPECT_LT((plan_->frames.back()[links + 2].translation().head<2>() - Eigen::Vector2d(-0.9, -0.9)).norm(),
              0.01 * std::sqrt(2.0) + 1e-9);
}

TEST_F(SceneHtmlOfSolution, ToolMovesAtMostViewerSpeedPerFrame)
{
    const double step = VIEWER_SPEED * plan_->frameStep;
    double longest = 0.0;
    for (std::size_t k = 0; k + 1 < plan_->toolPath.size(); ++k)
    {
        const double move = (plan_->toolPath[k + 1] - plan_->toolPath[k]).norm();
        EXPECT_LE(move, step + 1e-9) << "frame " << k;
        longest = std::max(longest, move);
    }
    // steady, not slower than needed: the longest step is close to the bound
    EXPECT_GT(longest, 0.5 * step);
}

TEST_F(SceneHtmlOfSolution, EveryWaypointIsAFrameInPathOrder)
{
    std::size_t from = 0;
    for (std::size_t i = 0; i < path().getStateCount(); ++i)
    {
        const Eigen::Vector3d tool = space().toolPosition(path().getState(i));
        std::size_t k = from;
        while (k < plan_->toolPath.size() && (plan_->toolPath[k] - tool).norm() > 1e-12)
            ++k;
        ASSERT_LT(k, plan_->toolPath.size()) << "waypoint " << i << " is no frame after frame " << from;
        from = k;
    }
}

TEST_F(SceneHtmlOfSolution, SegmentsAreContiguousAndCoverEveryFrame)
{
    ompl_core::test::expectContiguousSegments(*plan_);
}

TEST_F(SceneHtmlOfSolution, SegmentsAreThePathsLabelsWithRepeatsMergedAndTheirColours)
{
    std::vector<std::string> expected;
    for (const SegmentLabel &label : path().labels())
        if (expected.empty() || expected.back() != labelText(*scene_, label))
            expected.push_back(labelText(*scene_, label));
    std::vector<std::string> labels;
    for (const ompl_core::ViewerSegment &segment : plan_->segments)
    {
        labels.push_back(segment.label);
        const bool push = segment.label.rfind("push obj", 0) == 0 && segment.label.size() == 9 &&
                          segment.label[8] >= '1' && segment.label[8] <= '4';
        EXPECT_TRUE(segment.label == "transit" || push) << segment.label;
        EXPECT_EQ(segment.colour, push ? PUSH_COLOUR : TRANSIT_COLOUR) << segment.label;
    }
    EXPECT_EQ(labels, expected);
    EXPECT_NE(std::find(labels.begin(), labels.end(), "push obj3"), labels.end()) << "obj3 must be pushed";
}

TEST_F(SceneHtmlOfSolution, OnlyThePushedObjectMovesAndKeepsTheStandoffFromTheTool)
{
    const std::size_t links = shapedLinks(*setup_).size();
    for (const ompl_core::ViewerSegment &segment : plan_->segments)
    {
        const int pushed = segment.label == "transit" ? -1 : segment.label.back() - '1';
        for (std::size_t k = segment.first; k < segment.last; ++k)
            for (int i = 0; i < 4; ++i)
            {
                const Eigen::Vector3d a = plan_->frames[k][links + static_cast<std::size_t>(i)].translation(),
                                      b = plan_->frames[k + 1][links + static_cast<std::size_t>(i)]
                                              .translation();
                if (i != pushed)
                    ASSERT_LT((b - a).norm(), 1e-12)
                        << segment.label << " moves obj" << i + 1 << " at frame " << k;
                else
                    ASSERT_NEAR((plan_->toolPath[k + 1] - b).head<2>().norm(), STANDOFF, 1e-6)
                        << segment.label << " at frame " << k + 1;
            }
    }
}

TEST_F(SceneHtmlOfSolution, GoalOfObj3IsTranslucentAtItsGoalPosition)
{
    const ompl_core::ViewerBody *goal = ompl_core::test::bodyNamed(plan_->goals, "goal obj3");
    ASSERT_NE(goal, nullptr);
    EXPECT_LT(goal->opacity, 1.0);
    ASSERT_EQ(goal->solids.size(), 1u);
    const double halfHeight = scene_->objects[2].shape.height() / 2;  // the cylinder's 0.5 m / 2
    EXPECT_LT((goal->solids[0].pose.translation() - Eigen::Vector3d(-0.9, -0.9, halfHeight)).norm(), 1e-12)
        << goal->solids[0].pose.translation().transpose();
    EXPECT_EQ(goal->solids[0].kind, ompl_core::ViewerSolid::Kind::Cylinder);
    EXPECT_DOUBLE_EQ(goal->solids[0].radius, 0.2);
    EXPECT_DOUBLE_EQ(goal->solids[0].length, 0.5);
    // the other objects have no goal
    for (const char *name : {"goal obj1", "goal obj2", "goal obj4"})
        EXPECT_EQ(ompl_core::test::bodyNamed(plan_->goals, name), nullptr) << name;
}

TEST_F(SceneHtmlOfSolution, RobotGoalIsTranslucentAtTheGoalJoints)
{
    // every joint has a goal (0, 0): the sphere at its link origin (0, 0, 0.25)
    const ompl_core::ViewerBody *goal = ompl_core::test::bodyNamed(plan_->goals, "goal robot");
    ASSERT_NE(goal, nullptr);
    EXPECT_LT(goal->opacity, 1.0);
    ASSERT_EQ(goal->solids.size(), 1u);
    EXPECT_LT((goal->solids[0].pose.translation() - Eigen::Vector3d(0.0, 0.0, 0.25)).norm(), 1e-12);
}

TEST_F(SceneHtmlOfSolution, FixedBodiesIncludeEveryObstacle)
{
    for (const Obstacle &obstacle : scene_->obstacles)
    {
        const ompl_core::ViewerBody *body = ompl_core::test::bodyNamed(plan_->fixed, obstacle.name);
        ASSERT_NE(body, nullptr) << obstacle.name;
        ASSERT_EQ(body->solids.size(), 1u);
        EXPECT_TRUE(body->solids[0].pose.isApprox(obstacle.pose, 1e-12)) << obstacle.name;
        EXPECT_TRUE(body->solids[0].size.isApprox(obstacle.shape.boxSize, 1e-12)) << obstacle.name;
    }
    EXPECT_EQ(scene_->obstacles.size(), 7u);
    EXPECT_NE(ompl_core::test::bodyNamed(plan_->fixed, "floor"), nullptr) << "the support surface";
}

TEST(SceneHtml, MeshRobotShowsItsVisualMeshesInTheirColoursAtItsLinkFrames)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const ManipulationSetup setup(pandaPickScene());
    const ompl_core::ViewerPlan plan = manipulationViewerPlan(setup, nullptr, "panda");
    const RobotModel &robot = setup.model()->robot();
    const VisualModel look = VisualModel::fromUrdfFile(setup.model()->scene().robot.urdfFile, robot);
    std::vector<Eigen::Isometry3d> frames;
    robot.forwardKinematics(
        setup.manipulationSpace()->robotValues(setup.getProblemDefinition()->getStartState(0)),
        setup.model()->scene().robot.basePose, frames);

    // the links with shapes, in link order, each at its link frame, then the cylinder
    std::size_t body = 0;
    std::set<std::string> colours;
    std::map<std::string, const ompl_core::ViewerMesh *> fingerMeshes;
    for (std::size_t l = 0; l < robot.links().size(); ++l)
    {
        if (look.links()[l].shapes.empty())
            continue;
        ASSERT_LT(body, plan.moving.size());
        const ompl_core::ViewerBody &link = plan.moving[body];
        EXPECT_EQ(link.name, robot.links()[l].name);
        ASSERT_EQ(link.solids.size(), look.links()[l].shapes.size()) << link.name;
        for (const ompl_core::ViewerSolid &solid : link.solids)
        {
            ASSERT_EQ(solid.kind, ompl_core::ViewerSolid::Kind::Mesh);
            ASSERT_NE(solid.mesh, nullptr) << "a shared mesh";
            EXPECT_LE(solid.mesh->vertices.size(), MeshReduction().maxVertices);
            colours.insert(solid.colour);
        }
        fingerMeshes[link.name] = link.solids.front().mesh.get();
        EXPECT_TRUE(plan.frames[0][body].isApprox(frames[l], 1e-12)) << link.name;
        ++body;
    }
    ASSERT_EQ(plan.moving.size(), body + 1);
    EXPECT_EQ(plan.moving.back().name, "cyl1");
    EXPECT_TRUE(colours.count("#ffffff") == 1 && colours.count("#404040") == 1)
        << "white links, dark grey joints (the .mtl colours)";
    EXPECT_EQ(colours.count(""), 0u) << "every solid has a colour of its own";
    EXPECT_EQ(fingerMeshes["panda_leftfinger"], fingerMeshes["panda_rightfinger"]) << "one file, one mesh";
    // the goal robot (the "ready" state) draws the same meshes again
    const ompl_core::ViewerBody *goal = ompl_core::test::bodyNamed(plan.goals, "goal robot");
    ASSERT_NE(goal, nullptr);
    std::set<const ompl_core::ViewerMesh *> linkMeshes;
    for (std::size_t b = 0; b < body; ++b)
        for (const ompl_core::ViewerSolid &solid : plan.moving[b].solids)
            linkMeshes.insert(solid.mesh.get());
    for (const ompl_core::ViewerSolid &solid : goal->solids)
        EXPECT_EQ(linkMeshes.count(solid.mesh.get()), 1u);

    // the page holds each mesh once and stays small
    std::ostringstream page;
    writeSceneHtml(page, setup, nullptr, "panda");
    std::size_t written = 0;
    for (std::size_t at = page.str().find("\"vertices\":["); at != std::string::npos;
         at = page.str().find("\"vertices\":[", at + 1))
        ++written;
    EXPECT_EQ(written, linkMeshes.size()) << "the cylinder and the tables are no meshes";
    EXPECT_LT(page.str().size(), 3u << 20u);
}

TEST(SceneHtml, SurfaceSlabsStandAboveTheObstacleTopsTheyLieOn)
{
    // a slab sunk into its table top would fight with the top's face for the same pixels
    const ManipulationSetup setup(pandaPickScene());
    const ompl_core::ViewerPlan plan = manipulationViewerPlan(setup, nullptr, "panda");
    const ompl_core::ViewerBody *slab = ompl_core::test::bodyNamed(plan.fixed, "table1");
    ASSERT_NE(slab, nullptr);
    const ompl_core::ViewerSolid &solid = slab->solids.at(0);
    const double top = solid.pose.translation().z() + solid.size.z() / 2.0;
    EXPECT_GT(top, 0.43 + 5e-4) << "above the table top at 0.43 m";
    EXPECT_LE(top, 0.43 + 2e-3) << "objects resting on it sink in no more than 2 mm";
    // the floor slab is drawn light, the tables' tops (at the lowest surface's height) too
    EXPECT_EQ(ompl_core::test::bodyNamed(plan.fixed, "floor")->colour, FLOOR_COLOUR);
}

TEST_F(SceneHtmlOfSolution, CompanionsFollowTheirPosesAtEveryWaypointBesideThePlannedObjects)
{
    // companions one metre east of the planned objects at every waypoint
    CompanionPoses companions{"shifted", {}};
    for (std::size_t i = 0; i < path().getStateCount(); ++i)
    {
        std::vector<ObjectPose> &poses = companions.poses.emplace_back();
        for (unsigned int k = 0; k < space().objectCount(); ++k)
        {
            poses.push_back(space().objectPose(path().getState(i), k));
            poses.back().position.x() += 1.0;
        }
    }
    const ompl_core::ViewerPlan plan = manipulationViewerPlan(*setup_, &path(), "companions", &companions);
    const std::size_t objects = space().objectCount();
    const std::size_t links = plan_->moving.size() - objects;
    ASSERT_EQ(plan.moving.size(), links + 2 * objects);
    EXPECT_EQ(plan.moving[links + objects].name, scene_->objects[0].name + " (shifted)");
    EXPECT_LT(plan.moving[links + objects].opacity, 1.0);
    EXPECT_EQ(plan.tracks.size(), 2 * objects) << "the courses of the objects and of their companions";
    ASSERT_EQ(plan.frames.size(), plan_->frames.size()) << "the same timeline";
    for (std::size_t f = 0; f < plan.frames.size(); ++f)
        for (std::size_t k = 0; k < objects; ++k)
            EXPECT_TRUE(plan.frames[f][links + objects + k].translation().isApprox(
                plan.frames[f][links + k].translation() + Eigen::Vector3d(1.0, 0.0, 0.0), 1e-9))
                << "frame " << f << ", object " << k;
    CompanionPoses tooFew{"short", {companions.poses.front()}};
    EXPECT_THROW(manipulationViewerPlan(*setup_, &path(), "bad", &tooFew), ompl::Exception);
}
