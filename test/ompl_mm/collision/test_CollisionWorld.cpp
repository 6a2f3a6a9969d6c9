// Tests for CollisionWorld.
#include "ompl_mm/collision/CollisionWorld.h"

#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/SceneRobot.h"

#include "common/MobileArm.h"
#include "common/MobileBlocked.h"
#include "common/PandaPick.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

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

TEST(CollisionWorldGrasp, LinksBelowTheToolLinkMayTouchTheHeldObjectAndNoOthers)
{
    // mimic_gripper's tool link is its hand; the fingers (and the knuckle and tip below the left
    // one) hang below it. A 1 cm cube held between the open left finger's sides, above the hand,
    // touches that finger only; moved onto the base, it touches the base, not below the hand.
    Scene scene;
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/mimic_gripper.urdf";
    scene.robot.toolLink = "hand";
    MovableObject cube;
    cube.name = "cube";
    cube.shape.boxSize = Eigen::Vector3d::Constant(0.01);
    scene.objects.push_back(cube);
    const ManipulationModelPtr model = makeModel(scene);
    const CollisionWorld world(model);
    const RobotModel &robot = model->robot();
    const std::vector<double> q{0.3, 0.04};  // wrist, left finger (fully open)
    const Eigen::Isometry3d hand =
        robot.linkFrame(q.data(), Eigen::Isometry3d::Identity(), robot.linkIndex("hand"));
    std::vector<ObjectPose> poses(1);
    poses[0].position =
        hand * Eigen::Vector3d(0.0, 0.05, 0.055);  // base centre: the cube spans z 0.055..0.065
    const std::vector<int> held{-1}, resting{0};
    std::string contact;
    EXPECT_TRUE(world.isCollisionFree({q.data(), &poses, &held}, &contact)) << contact;

    // the same cube not held is checked against the finger like any object
    scene.surfaces.push_back(supportSurface("floor", Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, 1), -1.0));
    const ManipulationModelPtr withFloor = makeModel(scene);
    EXPECT_FALSE(CollisionWorld(withFloor).isCollisionFree({q.data(), &poses, &resting}, &contact));
    EXPECT_EQ(contact, "robot link 'left_finger' and object 'cube'");

    poses[0].position = Eigen::Vector3d(0.0, 0.0, 0.045);  // into the base's top (z up to 0.05)
    EXPECT_FALSE(world.isCollisionFree({q.data(), &poses, &held}, &contact));
    EXPECT_EQ(contact, "robot link 'base' and object 'cube'");
}

TEST(CollisionWorldGrasp, GripperLinksTheSrdfListsMayTouchTheHeldObject)
{
    // the Panda's tool frame (panda_grasptarget) hangs below its hand, beside the fingers: its SRDF's
    // end effector lists the hand and the fingers, which may touch what the gripper holds
    const SceneRobot loaded = loadSceneRobot(pandaPickScene());
    const Scene &scene = loaded.scene;
    const ManipulationModelPtr model = std::make_shared<ManipulationModel>(scene, loaded.robot);
    ASSERT_FALSE(scene.robot.gripperLinks.empty());
    const CollisionWorld world(model);
    const RobotModel &robot = model->robot();
    const int finger = robot.linkIndex("panda_leftfinger");
    ASSERT_FALSE(robot.isInSubtree(finger, model->toolLink()));
    std::vector<Eigen::Isometry3d> frames;
    robot.forwardKinematics(scene.robotStart.data(), scene.robot.basePose, frames);
    // the cylinder (r 0.03, 0.07 long) about the left finger's origin
    std::vector<ObjectPose> poses{{frames[finger].translation() - Eigen::Vector3d(0.0, 0.0, 0.035), 0.0}};
    const std::vector<int> held{-1}, resting{0};
    std::string contact;
    EXPECT_TRUE(world.isCollisionFree({scene.robotStart.data(), &poses, &held}, &contact)) << contact;
    EXPECT_FALSE(world.isCollisionFree({scene.robotStart.data(), &poses, &resting}, &contact));
    // with a link the SRDF lists, not one below the tool frame
    const std::vector<std::string> &listed = scene.robot.gripperLinks;
    EXPECT_TRUE(std::any_of(listed.begin(), listed.end(),
                            [&contact](const std::string &link)
                            { return contact.rfind("robot link '" + link + "'", 0) == 0; }))
        << contact;
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

TEST(CollisionWorldSelf, LinksBuiltToTouchAreFoundAndNeverChecked)
{
    // base and link2 touch in every pose: not checked; link1 and link3 touch at zero but seldom
    // elsewhere: checked
    Scene scene;
    scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/robots/always_touching.urdf";
    scene.robot.toolLink = "link3";
    const CollisionWorld world(makeModel(scene));
    const std::vector<ObjectPose> objects;
    const std::vector<int> resting;
    std::string contact;
    const std::vector<double> apart{0.3, 0.0, 1.0};
    EXPECT_TRUE(world.isCollisionFree({apart.data(), &objects, &resting}, &contact)) << contact;
    const std::vector<double> zero{0.0, 0.0, 0.0};
    EXPECT_FALSE(world.isCollisionFree({zero.data(), &objects, &resting}, &contact));
    EXPECT_EQ(contact, "robot link 'link1' and robot link 'link3'");
}

namespace
{
    /** Motions of MOBILE BLOCKED's robot, and optionally one object with it, for checkSweep. */
    class MobileSweep : public MobileWorld
    {
    protected:
        using V2 = Eigen::Vector2d;

        /** Checks the robot's motion from a to b, moving object `pushed` (if >= 0) by the same. */
        CollisionWorld::SweepCheck sweep(const V2 &a, const V2 &b, int pushed = -1)
        {
            std::vector<double> qa{a.x(), a.y()}, qb{b.x(), b.y()};
            std::vector<ObjectPose> posesA = poses_, posesB = poses_;
            if (pushed >= 0)
                posesB[pushed].position.head<2>() += b - a;
            along_ = poses_;
            return world_.checkSweep(
                {qa.data(), &posesA, &resting_}, {qb.data(), &posesB, &resting_},
                [&](double t)
                {
                    const V2 at = a + t * (b - a);
                    joints_ = {at.x(), at.y()};
                    if (pushed >= 0)
                        along_[pushed].position =
                            posesA[pushed].position + t * (posesB[pushed].position - posesA[pushed].position);
                    return CollisionWorld::Configuration{joints_.data(), &along_, &resting_};
                });
        }

        /** Whether the robot alone is free at p. */
        bool freeAt(const V2 &p)
        {
            joints_ = {p.x(), p.y()};
            return free();
        }

        std::vector<ObjectPose> along_;
        // block2's corner nearest the room's centre, and the way from it that the robot passes by
        const V2 corner_{0.5, -0.5};
        const V2 away_ = V2(1.0, 1.0).normalized();
        const V2 along_line_ = V2(1.0, -1.0).normalized();
    };
}  // namespace

TEST_F(MobileSweep, APassThatGrazesACornerBetweenItsEndsCollides)
{
    poses_[1].position = Eigen::Vector3d(0.8, 1.0, 0.0);  // obj2 out of the way
    // 1 mm too close at the middle, free at both ends 5 cm apart (a check every 5 cm misses it)
    const V2 closest = corner_ + 0.199 * away_;
    const V2 a = closest - 0.025 * along_line_, b = closest + 0.025 * along_line_;
    ASSERT_TRUE(freeAt(a));
    ASSERT_TRUE(freeAt(b));
    ASSERT_FALSE(freeAt(closest));
    EXPECT_FALSE(sweep(a, b).free);
    EXPECT_FALSE(sweep(b, a).free);
}

TEST_F(MobileSweep, EveryPartOfAFreeMotionIsFree)
{
    poses_[1].position = Eigen::Vector3d(0.8, 1.0, 0.0);  // obj2 out of the way
    // passing the corner 1 mm clear: free, and so is any part of it, however it is cut
    const V2 closest = corner_ + 0.201 * away_;
    const V2 a = closest - 0.5 * along_line_, b = closest + 0.5 * along_line_;
    ASSERT_TRUE(sweep(a, b).free);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 200; ++k)
    {
        double s = unit(rng), t = unit(rng);
        if (s > t)
            std::swap(s, t);
        EXPECT_TRUE(sweep(a + s * (b - a), a + t * (b - a)).free) << s << " .. " << t;
    }
    // and 0.5 mm into the corner it is not
    const V2 inside = corner_ + 0.1995 * away_;
    EXPECT_FALSE(sweep(inside - 0.5 * along_line_, inside + 0.5 * along_line_).free);
}

TEST_F(MobileSweep, AMotionIntoAWallStopsSafelyShortOfIt)
{
    // straight down onto block2's top face (y = -0.5)
    const CollisionWorld::SweepCheck check = sweep(V2(0.0, 0.5), V2(0.0, -1.0));
    EXPECT_FALSE(check.free);
    const double y = 0.5 + check.safeFraction * (-1.5);
    EXPECT_GE(y, -0.5 + 0.2 + CollisionWorld::SAFE_CLEARANCE - 1e-9);
    EXPECT_LT(y, -0.5 + 0.2 + 0.05);  // and not far from it
}

TEST_F(MobileSweep, AMotionNeverSafelyClearIsSafeNowhere)
{
    // along block2's top face (y = -0.5) 5 mm clear of it, into block1's east face (x = -0.5):
    // block2 is measured only every few rounds, but it is never a safe clearance away
    const CollisionWorld::SweepCheck check = sweep(V2(0.3, -0.295), V2(-0.6, -0.295));
    ASSERT_FALSE(check.free);
    EXPECT_EQ(check.contact[1], "obstacle 'block1'");
    EXPECT_EQ(check.safeFraction, 0.0);
}

TEST_F(MobileSweep, APushKeepsTheRobotJustBehindTheObject)
{
    // the robot 1 cm behind obj2 (radii 0.2 + 0.2), both moving 0.2 m along +x
    const V2 behind(0.8 - 0.41, -0.1);
    const CollisionWorld::SweepCheck push = sweep(behind, behind + V2(0.2, 0.0), 1);
    EXPECT_TRUE(push.free);
    EXPECT_EQ(push.blockingObject, -1);
    // without the object moving, the robot runs into it
    const CollisionWorld::SweepCheck run = sweep(behind, behind + V2(0.2, 0.0));
    EXPECT_FALSE(run.free);
    EXPECT_EQ(run.blockingObject, 1) << "obj2 stopped the robot";
}

TEST_F(MobileSweep, AnObstacleBlocksWithoutAnObjectToBlame)
{
    EXPECT_EQ(sweep(V2(0.0, 0.5), V2(0.0, -1.0)).blockingObject, -1) << "block2's top";
}

TEST_F(MobileSweep, APushedObjectIsStoppedByTheObjectStandingInItsWay)
{
    // obj2 pushed 0.6 m along +x into obj1 standing 0.5 m ahead of it: obj1 is in the way
    poses_[0].position = poses_[1].position + Eigen::Vector3d(0.5, 0.0, 0.0);
    const V2 behind(0.8 - 0.41, -0.1);
    const CollisionWorld::SweepCheck check = sweep(behind, behind + V2(0.6, 0.0), 1);
    EXPECT_FALSE(check.free);
    EXPECT_EQ(check.blockingObject, 0);
}

namespace
{
    /** KUKA TABLE with the arm at its zero pose and cyl1 carried straight from one point to
        another, held at the start and resting where it ends. */
    class PutDown : public ::testing::Test
    {
    protected:
        PutDown() : scene_(loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml")), world_(makeModel(scene_))
        {
            for (const MovableObject &object : scene_.objects)
                poses_.push_back(object.start);
        }

        CollisionWorld::SweepCheck putDown(const Eigen::Vector3d &from, const Eigen::Vector3d &to)
        {
            std::vector<ObjectPose> posesFrom = poses_, posesTo = poses_, along = poses_;
            posesFrom[0].position = from;
            posesTo[0].position = to;
            std::vector<int> restingFrom(poses_.size()), restingTo(poses_.size()), restingAlong;
            for (std::size_t i = 0; i < poses_.size(); ++i)
            {
                restingFrom[i] = scene_.restingSurface(posesFrom[i].position);
                restingTo[i] = scene_.restingSurface(posesTo[i].position);
            }
            const std::vector<double> zero(7, 0.0);
            return world_.checkSweep(
                {zero.data(), &posesFrom, &restingFrom}, {zero.data(), &posesTo, &restingTo},
                [&](double t)
                {
                    along[0].position = from + t * (to - from);
                    restingAlong = restingFrom;
                    restingAlong[0] = scene_.restingSurface(along[0].position);
                    return CollisionWorld::Configuration{zero.data(), &along, &restingAlong};
                });
        }

        Scene scene_;
        CollisionWorld world_;
        std::vector<ObjectPose> poses_;
    };
}  // namespace

TEST_F(PutDown, AnObjectPutOnATableFromAboveIsFree)
{
    // table1's top spans z 0.38 to 0.43 around (0.5, 0)
    const Eigen::Vector3d onTop(0.5, 0.0, 0.43);
    ASSERT_GE(scene_.restingSurface(onTop), 0);
    EXPECT_TRUE(putDown(onTop + Eigen::Vector3d(0.0, 0.0, 0.1), onTop).free);
    // and lifted off it
    EXPECT_TRUE(putDown(onTop, onTop + Eigen::Vector3d(0.0, 0.0, 0.1)).free);
}

TEST_F(PutDown, AnObjectPutOnATableThroughItsTopCollides)
{
    // from under the top (clear of the legs) up through it: it may touch the table where it
    // rests, but not pass through it on the way
    const Eigen::Vector3d onTop(0.5, 0.0, 0.43), under(0.5, 0.0, 0.2);
    std::string contact;
    ASSERT_TRUE(world_
                    .contactAmong(std::vector<double>(7, 0.0).data(),
                                  {ObjectPose{under, 0.0}, std::nullopt, std::nullopt})
                    .empty());
    EXPECT_FALSE(putDown(under, onTop).free);
    EXPECT_FALSE(putDown(onTop, under).free);
}

TEST_F(PutDown, AnObjectSlidOntoATableSunkBelowItsTopCollides)
{
    // from beside table1's top (x up to 0.77), 0.5 mm below its surface, onto it: half way it is
    // off the surface's rectangle (x up to 0.75) and 0.25 mm too low to rest, yet inside the top
    const double surface = 0.43;
    const Eigen::Vector3d beside(0.85, 0.0, surface - 5e-4), onTop(0.7, 0.0, surface);
    ASSERT_GE(scene_.restingSurface(onTop), 0);
    const Eigen::Vector3d halfWay = 0.5 * (beside + onTop);
    ASSERT_LT(scene_.restingSurface(halfWay), 0);
    const std::vector<double> zero(7, 0.0);
    EXPECT_EQ(world_.contactAmong(zero.data(), {ObjectPose{beside, 0.0}, std::nullopt, std::nullopt}), "");
    EXPECT_EQ(world_.contactAmong(zero.data(), {ObjectPose{halfWay, 0.0}, std::nullopt, std::nullopt}),
              "object 'cyl1' and obstacle 'table1_top'");
    EXPECT_FALSE(putDown(beside, onTop).free);
    EXPECT_FALSE(putDown(onTop, beside).free);
}

TEST_F(PutDown, AnObjectLoweredOntoATableTouchesItOnlyWhereItRests)
{
    // straight down onto table1 but ending a little inside its top, as far as the rest tolerance
    // allows: free, the object resting wherever it touches
    const double sunk = 0.43 - 0.5 * SupportSurface::REST_TOLERANCE;
    const Eigen::Vector3d above(0.5, 0.0, 0.5), onTop(0.5, 0.0, sunk);
    ASSERT_GE(scene_.restingSurface(onTop), 0);
    EXPECT_TRUE(putDown(above, onTop).free);
    EXPECT_TRUE(putDown(onTop, above).free);
}

TEST_F(PutDown, AnObjectOnTheEdgeOfATableIsLiftedStraightUp)
{
    // table1's surface ends at x 0.75 (its top at 0.77): an object may stand on the edge
    const Eigen::Vector3d onEdge(0.75, 0.25, 0.43), above(0.75, 0.25, 0.5);
    ASSERT_GE(scene_.restingSurface(onEdge), 0);
    EXPECT_TRUE(putDown(onEdge, above).free);
    EXPECT_TRUE(putDown(above, onEdge).free);
}

TEST(ArmSweep, ArmMotionsFoundFreeAreFreeEverywhereAndBlockedOnesSafeWhereTheyStop)
{
    // KUKA TABLE's arm among its tables and cylinders: pairs far apart are measured only every few
    // rounds (when their last measure no longer bounds them), the near ones every round
    const Scene scene = loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml");
    const ManipulationModelPtr model = makeModel(scene);
    const CollisionWorld world(model);
    const RobotModel &robot = model->robot();
    std::vector<ObjectPose> poses;
    std::vector<int> resting;
    for (const MovableObject &object : scene.objects)
    {
        poses.push_back(object.start);
        resting.push_back(scene.restingSurface(object.start.position));
    }
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto randomPose = [&]
    {
        std::vector<double> q(robot.dof());
        for (unsigned int i = 0; i < robot.dof(); ++i)
            q[i] = robot.variableJoint(i).lower +
                   unit(rng) * (robot.variableJoint(i).upper - robot.variableJoint(i).lower);
        return q;
    };
    const auto isFree = [&](const std::vector<double> &q) {
        return world.isCollisionFree({q.data(), &poses, &resting});
    };
    unsigned int free = 0, blocked = 0;
    std::vector<double> along(robot.dof());
    const auto at = [&](const std::vector<double> &a, const std::vector<double> &b, double t)
    {
        for (unsigned int i = 0; i < robot.dof(); ++i)
            along[i] = a[i] + t * (b[i] - a[i]);
        return along;
    };
    for (int k = 0; k < 1000; ++k)
    {
        const std::vector<double> a = randomPose(), b = randomPose();
        if (!isFree(a) || !isFree(b))
            continue;
        const CollisionWorld::SweepCheck check =
            world.checkSweep({a.data(), &poses, &resting}, {b.data(), &poses, &resting},
                             [&](double t)
                             {
                                 at(a, b, t);
                                 return CollisionWorld::Configuration{along.data(), &poses, &resting};
                             });
        if (check.free)
        {
            ++free;
            for (int s = 1; s < 200; ++s)
                ASSERT_TRUE(isFree(at(a, b, s / 200.0))) << "motion " << k << " at " << s / 200.0;
        }
        else
        {
            ++blocked;
            EXPECT_FALSE(check.contact[0].empty()) << "motion " << k;
            EXPECT_TRUE(isFree(at(a, b, check.safeFraction))) << "motion " << k;
        }
    }
    EXPECT_GE(free, 20u);
    EXPECT_GE(blocked, 20u);
}

TEST(ArmSweep, ALinkThatStartsAtRestAndSpeedsUpIsStoppedByWhatItReaches)
{
    // the mobile arm's base slides along y while its shoulder turns so that, at the start, the elbow
    // stands still (the base's speed cancels the turn's); then it swings the forearm's sphere into
    // a box: the speed at the start alone would let the check leap over it
    Scene scene;
    scene.robot.toolLink = "hand";
    Obstacle box;
    box.name = "box";
    box.shape.kind = Shape::Kind::Box;
    box.shape.boxSize = Eigen::Vector3d(0.1, 0.1, 0.1);
    // where the forearm's sphere passes at three quarters of the way
    box.pose.translation() = Eigen::Vector3d(0.1 + 0.55 * std::cos(-2.25), 0.3 + 0.55 * std::sin(-2.25), 0.5);
    scene.obstacles.push_back(box);
    const ManipulationModelPtr model =
        std::make_shared<ManipulationModel>(scene, RobotModel::fromUrdfString(MOBILE_ARM, "mobile_arm"));
    const CollisionWorld world(model);
    const std::vector<ObjectPose> poses;
    const std::vector<int> resting;
    const std::vector<double> from{0.0, -0.6, 0.0, 0.0, 0.0}, to{0.0, 0.6, -3.0, 0.0, 0.0};
    std::vector<double> along(from.size());
    const auto at = [&](double t)
    {
        for (std::size_t i = 0; i < along.size(); ++i)
            along[i] = from[i] + t * (to[i] - from[i]);
        return CollisionWorld::Configuration{along.data(), &poses, &resting};
    };
    ASSERT_TRUE(world.isCollisionFree(at(0.0)));
    ASSERT_TRUE(world.isCollisionFree(at(1.0)));
    ASSERT_FALSE(world.isCollisionFree(at(0.75)));
    const CollisionWorld::SweepCheck check =
        world.checkSweep({from.data(), &poses, &resting}, {to.data(), &poses, &resting}, at);
    EXPECT_FALSE(check.free);
    EXPECT_EQ(check.contact[1], "obstacle 'box'");
    EXPECT_LT(check.safeFraction, 0.75);
}
