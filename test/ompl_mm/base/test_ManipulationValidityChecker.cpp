// Tests for ManipulationValidityChecker.
#include "ompl_mm/base/ManipulationValidityChecker.h"
#include "ompl_mm/geometric/ManipulationSetup.h"
#include "ompl_mm/scene/SceneLoader.h"

#include <ompl/base/SpaceInformation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ompl_mm;
namespace ob = ompl::base;

namespace
{
    constexpr double RADIUS = 0.2;  // robot disc and every object of MOBILE BLOCKED

    class MobileChecker : public ::testing::Test
    {
    protected:
        MobileChecker()
            : setup_(loadScene(OMPL_MM_SCENES_DIR "/mobile_blocked.xml")),
              space_(*setup_.manipulationSpace()),
              checker_(*setup_.validityChecker())
        {
            state_ = space_.cloneState(setup_.getProblemDefinition()->getStartState(0));
        }
        ~MobileChecker() override { space_.freeState(state_); }

        void robotAt(double x, double y)
        {
            space_.robotValues(state_)[0] = x;
            space_.robotValues(state_)[1] = y;
        }
        void objectAt(unsigned int i, double x, double y, double z = 0.0)
        {
            space_.setObjectPose(state_, i, {Eigen::Vector3d(x, y, z), 0.0});
        }
        static bool contains(const std::string &text, const std::string &part)
        {
            return text.find(part) != std::string::npos;
        }

        ManipulationSetup setup_;
        const ManipulationStateSpace &space_;
        ManipulationValidityChecker &checker_;
        ob::State *state_;
    };
}  // namespace

TEST_F(MobileChecker, StartIsValid)
{
    EXPECT_TRUE(checker_.isValid(state_));
    EXPECT_EQ(checker_.explain(state_), "");
}

TEST_F(MobileChecker, RobotInsideABlockIsInvalidAndNamed)
{
    robotAt(-1.0, 0.0);  // centre of block1
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "block1")) << why;
    EXPECT_TRUE(contains(why, "robot link 'body'")) << why;
}

TEST_F(MobileChecker, RobotOverlappingAnObjectIsInvalid)
{
    robotAt(0.8 + 0.3, -0.1);  // 0.3 from obj2's centre, less than 2 radii
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "object 'obj2'")) << why;
    EXPECT_TRUE(contains(why, "robot link")) << why;
}

TEST_F(MobileChecker, OverlappingObjectsAreInvalidAndNamed)
{
    objectAt(0, 0.8 + 0.3, -0.1);  // obj1 onto obj2
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "object 'obj1'")) << why;
    EXPECT_TRUE(contains(why, "object 'obj2'")) << why;
}

TEST_F(MobileChecker, ObjectInAWallIsInvalid)
{
    objectAt(0, 2.4, -1.0);  // reaches x = 2.6, the east wall starts at 2.5
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "wall_east")) << why;
    EXPECT_TRUE(contains(why, "obj1")) << why;
}

TEST_F(MobileChecker, JointOutOfLimitsIsInvalidAndNamed)
{
    robotAt(1.9, -2.6);
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "joint 'y'")) << why;
}

TEST_F(MobileChecker, AtMostOneObjectIsHeld)
{
    objectAt(0, -2.0, 0.3, 0.3);  // obj1 lifted: held, nothing else wrong
    EXPECT_TRUE(checker_.isValid(state_)) << checker_.explain(state_);
    objectAt(1, 0.8, -0.1, 0.3);  // obj2 lifted too
    EXPECT_FALSE(checker_.isValid(state_));
    const std::string why = checker_.explain(state_);
    EXPECT_TRUE(contains(why, "rest on no surface")) << why;
    EXPECT_TRUE(contains(why, "obj1") && contains(why, "obj2")) << why;
}

TEST_F(MobileChecker, TouchingDistanceBetweenRobotAndObject)
{
    // the robot sphere and obj2's cylinder overlap when their axes are closer than 2 radii
    const Eigen::Vector2d obj2(0.8, -0.1);
    for (double angle : {0.0, 2.0, 2.6, M_PI, -1.3})
    {
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        const Eigen::Vector2d clear = obj2 + (2 * RADIUS + 0.001) * direction;
        const Eigen::Vector2d touching = obj2 + (2 * RADIUS - 0.001) * direction;
        robotAt(clear.x(), clear.y());
        EXPECT_TRUE(checker_.isValid(state_)) << angle << " " << checker_.explain(state_);
        robotAt(touching.x(), touching.y());
        EXPECT_FALSE(checker_.isValid(state_)) << angle;
        EXPECT_TRUE(contains(checker_.explain(state_), "obj2")) << angle;
    }
}

TEST_F(MobileChecker, CountersCountQueries)
{
    checker_.resetCounters();
    EXPECT_EQ(checker_.queryCount(), 0u);
    EXPECT_TRUE(checker_.isValid(state_));
    EXPECT_EQ(checker_.queryCount(), 1u);
    EXPECT_EQ(checker_.freeQueryCount(), 1u);
    robotAt(-1.0, 0.0);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_EQ(checker_.queryCount(), 2u);
    EXPECT_EQ(checker_.freeQueryCount(), 1u);
    checker_.explain(state_);
    robotAt(1.9, 1.9);
    checker_.explain(state_);
    EXPECT_EQ(checker_.queryCount(), 2u);
    EXPECT_EQ(checker_.freeQueryCount(), 1u);
    checker_.resetCounters();
    EXPECT_EQ(checker_.queryCount(), 0u);
    EXPECT_EQ(checker_.freeQueryCount(), 0u);
}

TEST_F(MobileChecker, NanRobotJointIsInvalid)
{
    robotAt(std::numeric_limits<double>::quiet_NaN(), 1.9);
    EXPECT_FALSE(checker_.isValid(state_));
    EXPECT_NE(checker_.explain(state_), "");
}

TEST_F(MobileChecker, NanObjectPoseIsInvalid)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    objectAt(0, nan, 0.3);
    EXPECT_FALSE(checker_.isValid(state_));
    objectAt(0, -2.0, 0.3);
    space_.setObjectPose(state_, 0, {Eigen::Vector3d(-2.0, 0.3, 0.0), nan});
    EXPECT_FALSE(checker_.isValid(state_));
}

TEST(ManipulationValidityCheckerTable, RestingObjectMayTouchItsSurfaceObstacle)
{
    // a table 1 x 1 x 0.43 at (1, 1); a surface on its top; a small cylinder standing there
    Scene scene;
    scene.robot.urdfFile = OMPL_MM_SCENES_DIR "/robots/mobile_disc.urdf";
    scene.robot.toolLink = "body";
    Obstacle table;
    table.name = "table";
    table.shape.kind = Shape::Kind::Box;
    table.shape.boxSize = Eigen::Vector3d(1.0, 1.0, 0.43);
    table.pose.translation() = Eigen::Vector3d(1.0, 1.0, 0.215);
    scene.obstacles.push_back(table);
    SupportSurface floor;
    floor.name = "floor";
    floor.min = Eigen::Vector2d(-2.5, -2.5);
    floor.max = Eigen::Vector2d(2.5, 2.5);
    SupportSurface top;
    top.name = "table_top";
    top.min = Eigen::Vector2d(0.5, 0.5);
    top.max = Eigen::Vector2d(1.5, 1.5);
    top.height = 0.43;
    top.obstacle = "table";
    scene.surfaces = {floor, top};
    MovableObject cup;
    cup.name = "cup";
    cup.shape.kind = Shape::Kind::Cylinder;
    cup.shape.radius = 0.1;
    cup.shape.length = 0.2;
    scene.objects.push_back(cup);

    auto model = std::make_shared<ManipulationModel>(scene, RobotModel::fromUrdfFile(scene.robot.urdfFile));
    auto space = std::make_shared<ManipulationStateSpace>(model);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    ManipulationValidityChecker checker(si);
    ob::State *state = space->allocState();
    space->robotValues(state)[0] = -1.0;
    space->robotValues(state)[1] = -1.0;

    space->setObjectPose(state, 0, {Eigen::Vector3d(1.0, 1.0, 0.43), 0.0});
    ASSERT_EQ(space->restingSurface(state, 0), 1);
    EXPECT_TRUE(checker.isValid(state)) << checker.explain(state);

    // 1 cm lower it rests on nothing (held) and sinks into the table
    space->setObjectPose(state, 0, {Eigen::Vector3d(1.0, 1.0, 0.42), 0.0});
    ASSERT_LT(space->restingSurface(state, 0), 0);
    EXPECT_FALSE(checker.isValid(state));
    const std::string why = checker.explain(state);
    EXPECT_NE(why.find("table"), std::string::npos) << why;
    EXPECT_NE(why.find("cup"), std::string::npos) << why;

    // on the floor beside the table it is valid again; pushed into the table's side it is not
    space->setObjectPose(state, 0, {Eigen::Vector3d(0.3, 1.0, 0.0), 0.0});
    EXPECT_TRUE(checker.isValid(state)) << checker.explain(state);
    space->setObjectPose(state, 0, {Eigen::Vector3d(0.45, 1.0, 0.0), 0.0});
    EXPECT_FALSE(checker.isValid(state));
    space->freeState(state);
}
