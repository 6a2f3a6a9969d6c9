// Tests for PushMobile.
#include "ompl_mm/primitives/PushMobile.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr unsigned int OBJ2 = 1, OBJ4 = 3;
    using V2 = Eigen::Vector2d;

    class MobilePush : public MobileBlockedTest
    {
    protected:
        explicit MobilePush(const Scene &scene = mobileBlockedScene()) : MobileBlockedTest(scene) {}

        void robot(ob::State *s, const V2 &q) { setRobot(space_, s, q.x(), q.y()); }
        V2 robot(const ob::State *s) const { return V2(space_.robotValues(s)[0], space_.robotValues(s)[1]); }
        /** Moves object i of s to (p, z), keeping its yaw. */
        void object(ob::State *s, unsigned int i, const V2 &p, double z = 0.0)
        {
            setObject(space_, s, i, p.x(), p.y(), z, space_.objectYaw(s, i));
        }
        V2 object(const ob::State *s, unsigned int i) const { return space_.objectPosition(s, i).head<2>(); }

        PushMobile push_{&space_, STANDOFF};
        Trajectory trajectory_{&space_};
        ob::State *from_ = startCopy();
        ob::State *to_ = startCopy();
    };

    /** MOBILE BLOCKED with a second surface 0.2 high (no obstacle under it) over a free area. */
    Scene withLedge()
    {
        Scene scene = mobileBlockedScene();
        scene.surfaces.push_back(supportSurface("ledge", V2(0.5, 1.5), V2(1.5, 2.5), 0.2));
        return scene;
    }

    class LedgePush : public MobilePush
    {
    protected:
        LedgePush() : MobilePush(withLedge()) {}
    };
}  // namespace

TEST_F(MobilePush, NameKindAndStandoff)
{
    EXPECT_EQ(push_.name(), "push_mobile");
    EXPECT_EQ(push_.kind(), PrimitiveKind::Push);
    EXPECT_DOUBLE_EQ(push_.standoff(0), STANDOFF);
}

TEST_F(MobilePush, UsefulWhenAnObjectSlides)
{
    object(to_, OBJ2, V2(1.3, -0.1));
    EXPECT_TRUE(push_.isUseful(from_, to_));
    robot(to_, V2(0.0, 0.0));  // the robot may end anywhere
    EXPECT_TRUE(push_.isUseful(from_, to_));
}

TEST_F(MobilePush, NotUsefulWhenNothingMovesOrOnlyTheRobot)
{
    EXPECT_FALSE(push_.isUseful(from_, to_));
    robot(to_, V2(0.0, 0.0));
    EXPECT_FALSE(push_.isUseful(from_, to_));
}

TEST_F(MobilePush, NotUsefulWhenAnObjectIsLifted)
{
    object(to_, OBJ2, V2(0.8, -0.1), 0.3);  // lifted in place
    EXPECT_FALSE(push_.isUseful(from_, to_));
    object(to_, OBJ2, V2(1.3, -0.1), 0.3);  // lifted and moved
    EXPECT_FALSE(push_.isUseful(from_, to_));
    // another object lifted in both states spoils a slide of obj2
    object(to_, OBJ2, V2(1.3, -0.1));
    object(from_, OBJ4, V2(1.2, 1.9), 0.3);
    object(to_, OBJ4, V2(1.2, 1.9), 0.3);
    EXPECT_FALSE(push_.isUseful(from_, to_));
}

TEST_F(LedgePush, NotUsefulWhenTheHeightChanges)
{
    // obj4 from the floor onto the ledge: both rest, but it does not slide
    ASSERT_GE(space_.model()->scene().restingSurface(Eigen::Vector3d(1.0, 2.0, 0.2)), 0);
    object(to_, OBJ4, V2(1.0, 2.0), 0.2);
    EXPECT_FALSE(push_.isUseful(from_, to_));
    // it slides when the heights agree
    object(to_, OBJ4, V2(1.0, 2.0), 0.0);
    EXPECT_TRUE(push_.isUseful(from_, to_));
}

TEST_F(MobilePush, PropagatePlacesTheRobotBehindTheObject)
{
    const V2 start(0.8, -0.1), target(1.3, -0.1);
    object(to_, OBJ2, target);
    trajectory_.reset(from_);
    ASSERT_TRUE(push_.propagate(from_, to_, trajectory_));
    ASSERT_EQ(trajectory_.size(), 3u);
    const V2 direction = (target - start).normalized();

    // a transit to the standoff point behind the object; nothing else changes
    const ob::State *behind = trajectory_.state(1);
    EXPECT_EQ(trajectory_.label(0), (SegmentLabel{PrimitiveKind::Transit, -1}));
    EXPECT_NEAR((robot(behind) - (start - STANDOFF * direction)).norm(), 0.0, 1e-12);
    for (unsigned int i = 0; i < space_.objectCount(); ++i)
        EXPECT_FALSE(space_.objectMoves(from_, behind, i)) << i;

    // the push: object at its target, robot the standoff behind it, height and yaw kept
    const ob::State *pushed = trajectory_.state(2);
    EXPECT_EQ(trajectory_.label(1), (SegmentLabel{PrimitiveKind::Push, static_cast<int>(OBJ2)}));
    EXPECT_NEAR((robot(pushed) - (target - STANDOFF * direction)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((object(pushed, OBJ2) - target).norm(), 0.0, 1e-12);
    EXPECT_EQ(space_.objectPosition(pushed, OBJ2).z(), 0.0);
    EXPECT_EQ(space_.objectYaw(pushed, OBJ2), space_.objectYaw(from_, OBJ2));
    for (unsigned int i : {0u, 2u, 3u})
        EXPECT_FALSE(space_.objectMoves(from_, pushed, i)) << i;
}

TEST_F(MobilePush, PropagateAlongADiagonal)
{
    const V2 start(0.8, -0.1), target(1.1, -0.5);  // displacement (0.3, -0.4): direction (0.6, -0.8)
    object(to_, OBJ2, target);
    trajectory_.reset(from_);
    ASSERT_TRUE(push_.propagate(from_, to_, trajectory_));
    ASSERT_EQ(trajectory_.size(), 3u);
    const V2 direction(0.6, -0.8);
    EXPECT_NEAR((robot(trajectory_.state(1)) - (start - STANDOFF * direction)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((robot(trajectory_.state(2)) - (target - STANDOFF * direction)).norm(), 0.0, 1e-12);
    // the robot stays at the standoff from the object's centre while pushing
    EXPECT_NEAR((robot(trajectory_.state(2)) - object(trajectory_.state(2), OBJ2)).norm(), STANDOFF, 1e-12);
}

TEST_F(MobilePush, NoTransitWhenAlreadyBehindTheObject)
{
    const V2 target(1.3, -0.1);
    robot(from_, V2(0.8 - STANDOFF, -0.1));
    object(to_, OBJ2, target);
    trajectory_.reset(from_);
    ASSERT_TRUE(push_.propagate(from_, to_, trajectory_));
    ASSERT_EQ(trajectory_.size(), 2u);
    EXPECT_EQ(trajectory_.label(0).kind, PrimitiveKind::Push);
}

TEST_F(MobilePush, PushesTheSlidingObjectNearestToTheTool)
{
    object(to_, OBJ2, V2(1.0, -0.3));
    object(to_, OBJ4, V2(0.9, 1.9));
    // the tool at (1.9, 1.9): obj4 at 0.7 is nearer than obj2
    ASSERT_LT((V2(1.9, 1.9) - V2(1.2, 1.9)).norm(), (V2(1.9, 1.9) - V2(0.8, -0.1)).norm());
    trajectory_.reset(from_);
    ASSERT_TRUE(push_.propagate(from_, to_, trajectory_));
    EXPECT_EQ(trajectory_.label(trajectory_.size() - 2).object, static_cast<int>(OBJ4));
    EXPECT_FALSE(space_.objectMoves(from_, trajectory_.back(), OBJ2));

    // from next to obj2, obj2 goes first
    robot(from_, V2(0.8, 0.4));
    trajectory_.reset(from_);
    ASSERT_TRUE(push_.propagate(from_, to_, trajectory_));
    EXPECT_EQ(trajectory_.label(trajectory_.size() - 2).object, static_cast<int>(OBJ2));
    EXPECT_FALSE(space_.objectMoves(from_, trajectory_.back(), OBJ4));
}

TEST_F(MobilePush, PropagateWithoutASlidingObjectAppendsNothing)
{
    robot(to_, V2(0.0, 0.0));
    trajectory_.reset(from_);
    EXPECT_FALSE(push_.propagate(from_, to_, trajectory_));
    EXPECT_EQ(trajectory_.size(), 1u);
}

TEST_F(MobilePush, ConstructorRejectsStandoffsThatOverlapRobotAndObject)
{
    // robot and objects are discs of radius 0.2: robot and pushed object touch at 0.4
    EXPECT_THROW(PushMobile(&space_, 0.0), ompl::Exception);
    EXPECT_THROW(PushMobile(&space_, -0.1), ompl::Exception);
    EXPECT_THROW(PushMobile(&space_, std::numeric_limits<double>::quiet_NaN()), ompl::Exception);
    EXPECT_THROW(PushMobile(&space_, 0.399), ompl::Exception);
    EXPECT_NO_THROW(PushMobile(&space_, 0.4));
}

TEST_F(MobilePush, DefaultStandoffIsPerObjectFromTheFootprints)
{
    // robot radius + the object's footprint radius (a box's half diagonal) + clearance
    Scene scene = mobileBlockedScene();
    scene.objects[1].shape.kind = Shape::Kind::Box;
    scene.objects[1].shape.boxSize = {0.3, 0.4, 0.5};
    ManipulationStateSpace space(makeModel(scene));
    const PushMobile push(&space);
    EXPECT_DOUBLE_EQ(push.standoff(0), 0.2 + 0.2 + PushMobile::CLEARANCE);
    EXPECT_DOUBLE_EQ(push.standoff(1), 0.2 + 0.25 + PushMobile::CLEARANCE);
    EXPECT_THROW(PushMobile(&space, 0.41), ompl::Exception) << "0.41 is too small for the box";
    EXPECT_NO_THROW(PushMobile(&space, 0.45));
}

TEST(PushMobileRobot, ConstructorRejectsARobotWithoutPlanarBase)
{
    ManipulationStateSpace space(makeModel(unitArmScene()));
    EXPECT_THROW(PushMobile(&space, STANDOFF), ompl::Exception);
}

TEST_F(MobilePush, ConstructorMessagesNameTheStandoff)
{
    // the message carries the offending value
    auto message = [this](double standoff) -> std::string
    {
        try
        {
            PushMobile push(&space_, standoff);
        }
        catch (const ompl::Exception &e)
        {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(message(0.0), "push_mobile standoff must be positive, got 0.000000");
    EXPECT_EQ(message(-0.1), "push_mobile standoff must be positive, got -0.100000");
    EXPECT_EQ(message(0.3),
              "push_mobile standoff 0.3 leaves the robot overlapping object 'obj1' while pushing "
              "it: it must be at least 0.4 (robot footprint radius 0.2 + object footprint radius "
              "0.2); leave it out for 0.41");
    EXPECT_EQ(message(0.4), "");
}

TEST(PushMobileRobot, ArmRobotMessageNamesTheNeededBase)
{
    ManipulationStateSpace space(makeModel(unitArmScene()));
    try
    {
        PushMobile push(&space, STANDOFF);
        FAIL() << "no exception";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_EQ(std::string(e.what()),
                  "push_mobile needs a robot whose base moves along world x and y (two prismatic joints)");
    }
}
