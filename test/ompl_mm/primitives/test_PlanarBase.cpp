// Tests for PlanarBase: the base joints are found along world x and y, and placing the tool puts
// the tool point exactly where asked, for any other joint values and a shifted base.
#include "ompl_mm/primitives/PlanarBase.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace ompl_mm;
using namespace ompl_mm::test;

TEST(PlanarBase, PlacesTheToolOfMobileBlockedExactly)
{
    const Scene scene = mobileBlockedScene();
    const ManipulationModelPtr model = makeModel(scene);
    const PlanarBase base(*model);
    ASSERT_TRUE(base.exists());
    std::vector<double> q(model->dof(), 0.7);
    for (const Eigen::Vector2d &target : {Eigen::Vector2d(1.5, -2.0), Eigen::Vector2d(-0.3, 0.25)})
    {
        base.placeTool(target, q.data());
        EXPECT_LT((model->toolFrame(q.data()).translation().head<2>() - target).norm(), 1e-12);
    }
}

TEST(PlanarBase, FindsTheJointsUnderATurnedAndShiftedBase)
{
    Scene scene = mobileBlockedScene();
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/mobile_base_xy.urdf";
    scene.robot.toolLink = "body";
    scene.robot.toolOffset = Eigen::Isometry3d(Eigen::Translation3d(0.2, 0.0, 0.1));
    scene.robot.basePose.translation() = Eigen::Vector3d(3.0, -1.0, 0.0);
    const ManipulationModelPtr model = makeModel(scene);
    const PlanarBase base(*model);
    ASSERT_TRUE(base.exists());
    std::vector<double> q(model->dof(), 0.0);
    base.placeTool(Eigen::Vector2d(0.5, 0.5), q.data());
    EXPECT_LT((model->toolFrame(q.data()).translation().head<2>() - Eigen::Vector2d(0.5, 0.5)).norm(), 1e-12);

    // turned by 90 degrees, the y joint moves along world -x: the axes must be world +x and +y
    scene.robot.basePose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    EXPECT_FALSE(PlanarBase(*makeModel(scene)).exists());
}

TEST(PlanarBase, AnArmHasNone)
{
    const ManipulationModelPtr model = makeModel(unitArmScene());
    EXPECT_FALSE(PlanarBase(*model).exists());
}

TEST(PlanarBase, FootprintRadiusHoldsEveryShapeAboutTheTool)
{
    const Scene scene = mobileBlockedScene();
    EXPECT_DOUBLE_EQ(PlanarBase(*makeModel(scene)).footprintRadius(scene.robotStart.data()), 0.2);

    // a box body 0.2 m behind the tool point counts with its bounding sphere
    Scene boxed = scene;
    boxed.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/mobile_base_xy.urdf";
    boxed.robot.toolLink = "body";
    boxed.robot.toolOffset = Eigen::Isometry3d(Eigen::Translation3d(0.2, 0.0, 0.1));
    EXPECT_DOUBLE_EQ(PlanarBase(*makeModel(boxed)).footprintRadius(boxed.robotStart.data()),
                     0.2 + 0.5 * std::sqrt(0.4 * 0.4 + 0.3 * 0.3 + 0.2 * 0.2));
}

TEST(PlanarBase, AnArmOnTheBaseCountsInTheFootprintAndIsNoBaseJoint)
{
    Scene scene = mobileBlockedScene();
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/mobile_base_arm.urdf";
    scene.robot.toolLink = "body";
    const ManipulationModelPtr model = makeModel(scene);
    const PlanarBase base(*model);
    ASSERT_TRUE(base.exists());
    const std::vector<double> q{1.0, 2.0, 0.3};
    EXPECT_DOUBLE_EQ(base.footprintRadius(q.data()), 0.5 + 0.05) << "the hand reaches farthest";
    for (int moved = 0; moved < 3; ++moved)
    {
        std::vector<double> other = q;
        other[moved] += 1e-12;
        EXPECT_EQ(base.onlyBaseMoves(q.data(), other.data()), moved < 2) << "joint " << moved;
    }
}
