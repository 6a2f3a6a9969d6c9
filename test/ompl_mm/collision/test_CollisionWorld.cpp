// Tests for CollisionWorld.
#include "ompl_mm/collision/CollisionWorld.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** MOBILE BLOCKED's start as a configuration that tests may change. */
    class MobileWorld : public ::testing::Test
    {
    protected:
        MobileWorld() : scene_(mobileBlockedScene()), model_(makeModel(scene_)), world_(model_)
        {
            joints_ = scene_.robotStart;
            for (const MovableObject &object : scene_.objects)
                poses_.push_back(object.start);
            resting_.assign(poses_.size(), 0);  // all on the floor (surface 0)
        }

        CollisionWorld::Configuration configuration() const { return {joints_.data(), &poses_, &resting_}; }
        bool free(std::string *contact = nullptr) const
        {
            return world_.isCollisionFree(configuration(), contact);
        }

        Scene scene_;
        ManipulationModelPtr model_;
        CollisionWorld world_;
        std::vector<double> joints_;
        std::vector<ObjectPose> poses_;
        std::vector<int> resting_;
    };
}  // namespace

TEST(MakeCollisionGeometry, SizesMatchTheShape)
{
    Shape box;
    box.kind = Shape::Kind::Box;
    box.boxSize = Eigen::Vector3d(0.3, 0.4, 0.5);
    const auto fclBox = std::dynamic_pointer_cast<fcl::Boxd>(makeCollisionGeometry(box));
    ASSERT_TRUE(fclBox);
    EXPECT_DOUBLE_EQ(fclBox->side.x(), 0.3);
    EXPECT_DOUBLE_EQ(fclBox->side.y(), 0.4);
    EXPECT_DOUBLE_EQ(fclBox->side.z(), 0.5);

    Shape cylinder;
    cylinder.kind = Shape::Kind::Cylinder;
    cylinder.radius = 0.2;
    cylinder.length = 0.5;
    const auto fclCylinder = std::dynamic_pointer_cast<fcl::Cylinderd>(makeCollisionGeometry(cylinder));
    ASSERT_TRUE(fclCylinder);
    EXPECT_DOUBLE_EQ(fclCylinder->radius, 0.2);
    EXPECT_DOUBLE_EQ(fclCylinder->lz, 0.5);

    Shape sphere;
    sphere.kind = Shape::Kind::Sphere;
    sphere.radius = 0.15;
    const auto fclSphere = std::dynamic_pointer_cast<fcl::Sphered>(makeCollisionGeometry(sphere));
    ASSERT_TRUE(fclSphere);
    EXPECT_DOUBLE_EQ(fclSphere->radius, 0.15);
    EXPECT_DOUBLE_EQ(sphere.height(), 0.3);
}

TEST_F(MobileWorld, StartIsFree)
{
    std::string contact = "untouched";
    EXPECT_TRUE(free(&contact));
    EXPECT_TRUE(free());
}

TEST_F(MobileWorld, RobotAgainstObstacleNamesBoth)
{
    joints_ = {0.0, -1.0};  // centre of block2
    std::string contact;
    EXPECT_FALSE(free(&contact));
    EXPECT_EQ(contact, "robot link 'body' and obstacle 'block2'");
    EXPECT_FALSE(free());  // no contact string wanted

    // a disc of radius 0.2 beside block2's face (y = -0.5): free at 0.21, in collision at 0.19
    joints_ = {0.0, -0.5 + 0.21};
    EXPECT_TRUE(free());
    joints_ = {0.0, -0.5 + 0.19};
    EXPECT_FALSE(free());
}

TEST_F(MobileWorld, ObjectAgainstObjectNamesBoth)
{
    poses_[3].position = poses_[1].position + Eigen::Vector3d(0.35, 0.0, 0.0);  // obj4 onto obj2
    std::string contact;
    EXPECT_FALSE(free(&contact));
    EXPECT_EQ(contact, "object 'obj2' and object 'obj4'");
    poses_[3].position = poses_[1].position + Eigen::Vector3d(0.0, 0.41, 0.0);
    EXPECT_TRUE(free(&contact)) << contact;
}

TEST_F(MobileWorld, ObjectAgainstObstacleNamesBoth)
{
    poses_[0].position = Eigen::Vector3d(-1.0, 0.65, 0.0);  // obj1 0.15 from block1's face (y = 0.5)
    std::string contact;
    EXPECT_FALSE(free(&contact));
    EXPECT_EQ(contact, "object 'obj1' and obstacle 'block1'");
    poses_[0].position = Eigen::Vector3d(-1.0, 0.75, 0.0);
    EXPECT_TRUE(free(&contact)) << contact;
}

TEST_F(MobileWorld, RobotAgainstRestingObjectCollides)
{
    joints_ = {0.8 + 0.3, -0.1};  // 0.3 from obj2
    std::string contact;
    EXPECT_FALSE(free(&contact));
    EXPECT_EQ(contact, "robot link 'body' and object 'obj2'");
}

TEST_F(MobileWorld, HeldObjectMayTouchTheGripper)
{
    // the body is the tool link: a held object (resting surface -1) may overlap it
    joints_ = {0.8 + 0.3, -0.1};
    resting_[1] = -1;
    std::string contact;
    EXPECT_TRUE(free(&contact)) << contact;
    // but a held object still collides with obstacles and other objects
    poses_[1].position = Eigen::Vector3d(0.0, -0.6, 0.3);  // held, partly inside block2
    joints_ = {0.0, 0.0};
    EXPECT_FALSE(free(&contact));
    EXPECT_EQ(contact, "object 'obj2' and obstacle 'block2'");
}

TEST_F(MobileWorld, OverlapIsSymmetricInTheObjectPair)
{
    // the pair is reported once, lower index first, whichever object moved
    poses_[1].position = poses_[3].position + Eigen::Vector3d(-0.3, 0.0, 0.0);  // obj2 onto obj4
    std::string contact;
    EXPECT_FALSE(free(&contact));
    EXPECT_EQ(contact, "object 'obj2' and object 'obj4'");
}

TEST(CollisionWorldInput, SurfaceNamingAnUnknownObstacleThrows)
{
    Scene scene = mobileBlockedScene();
    scene.surfaces[0].obstacle = "no_such_table";
    const ManipulationModelPtr model = makeModel(scene);
    const std::string what = inputErrorOf([&] { CollisionWorld world(model); });
    ASSERT_NE(what, "") << "no ompl_core::InputError";
    EXPECT_TRUE(startsWith(what, scene.surfaces[0].where.str() + ": ")) << what;
    EXPECT_TRUE(contains(what, "no_such_table")) << what;
}

TEST(CollisionWorldSelf, AdjacentLinksMayTouchWhateverTheirOrder)
{
    // planar_2link's base box and first link's cylinder overlap at the first joint, and the first
    // link's end meets the second link's box at the second joint: adjacent links are never checked
    Scene scene;
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/planar_2link.urdf";
    scene.robot.toolLink = "tool";
    const ManipulationModelPtr model = makeModel(scene);
    const CollisionWorld world(model);
    const std::vector<ObjectPose> objects;
    const std::vector<int> resting;
    std::string contact;
    for (const std::vector<double> &q : {std::vector<double>{0.0, 0.0}, std::vector<double>{1.0, -2.0}})
        EXPECT_TRUE(world.isCollisionFree({q.data(), &objects, &resting}, &contact)) << contact;
}
