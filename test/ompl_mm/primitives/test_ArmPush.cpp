// Tests for ArmPush, on KUKA CABINET's three push primitives and MEKA CLEAN-UP's bottle1.
#include "ompl_mm/primitives/ArmPush.h"

#include "ompl_core/run/GlobalSeed.h"
#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace ompl_mm;
namespace ob = ompl::base;

namespace
{
    /** cyl3 of KUKA CABINET, nearest to the robot at the start. */
    constexpr unsigned int CYL3 = 2;
    /** Samples per push segment at which the tests look at the tool. */
    constexpr unsigned int SAMPLES = 50;
    /** The tests push cyl3 away from the robot and to its left, at 45 degrees, which every hand
        reaches. */
    const double DIAGONAL = std::sqrt(0.5);
    /** Propagations a test tries before it calls a push unreachable. */
    constexpr unsigned int ATTEMPTS = 5;
    /** KUKA CABINET's longest push, metres. */
    constexpr double MAX_PUSH = 0.1;

    class ArmPushTest : public ::testing::TestWithParam<std::string>
    {
    protected:
        ArmPushTest()
        {
            ompl_core::reseedOmpl(1);
            setup_ = std::make_unique<ManipulationSetup>(loadScene(OMPL_MM_SCENES_DIR "/kuka_cabinet.xml"));
            space_ = setup_->manipulationSpace().get();
            for (const PrimitivePtr &primitive : setup_->primitives())
                if (primitive->name() == GetParam())
                    push_ = std::dynamic_pointer_cast<ArmPush>(primitive);
            from_ = space_->allocState();
            to_ = space_->allocState();
            space_->copyState(from_, setup_->getProblemDefinition()->getStartState(0));
            space_->copyState(to_, from_);
        }
        ~ArmPushTest() override
        {
            space_->freeState(from_);
            space_->freeState(to_);
        }

        /** Moves cyl3 in `to_` by (dx, dy) from where `from_` has it. */
        void pushCyl3By(double dx, double dy)
        {
            ObjectPose pose = space_->objectPose(from_, CYL3);
            pose.position += Eigen::Vector3d(dx, dy, 0.0);
            space_->setObjectPose(to_, CYL3, pose);
        }

        /** Propagates the push from `from_` to `to_` into trajectory, trying a few times: the
            scene's push has a small IK budget (5 restarts) and may miss a reachable pose. */
        bool propagate(Trajectory &trajectory) const
        {
            for (unsigned int attempt = 0; attempt < ATTEMPTS; ++attempt)
            {
                trajectory.reset(from_);
                if (push_->propagate(from_, to_, trajectory))
                    return true;
            }
            return false;
        }

        /** The motion validator of the setup. */
        const ManipulationMotionValidator &validator() const
        {
            return static_cast<const ManipulationMotionValidator &>(
                *setup_->getSpaceInformation()->getMotionValidator());
        }

        std::unique_ptr<ManipulationSetup> setup_;
        const ManipulationStateSpace *space_{nullptr};
        std::shared_ptr<ArmPush> push_;
        ob::State *from_{nullptr};
        ob::State *to_{nullptr};
    };

    /** The distance of point p from the line through a in direction d (a unit vector). */
    double distanceFromLine(const Eigen::Vector3d &p, const Eigen::Vector3d &a, const Eigen::Vector3d &d)
    {
        const Eigen::Vector3d v = p - a;
        return (v - v.dot(d) * d).norm();
    }
}  // namespace

TEST_P(ArmPushTest, PushesAlongAStraightToolLineMovingOnlyItsObject)
{
    ASSERT_NE(push_, nullptr);
    pushCyl3By(DIAGONAL * 0.08, DIAGONAL * 0.08);
    ASSERT_TRUE(push_->isUseful(from_, to_));
    Trajectory trajectory(space_);
    ASSERT_TRUE(propagate(trajectory));

    const Eigen::Vector3d direction(DIAGONAL, DIAGONAL, 0.0);
    unsigned int pushes = 0;
    ob::State *between = space_->allocState();
    for (std::size_t k = 0; k + 1 < trajectory.size(); ++k)
    {
        const ob::State *a = trajectory.state(k);
        const ob::State *b = trajectory.state(k + 1);
        const SegmentLabel label = trajectory.label(k);
        const std::optional<SegmentLabel> explained = validator().explain(a, b);
        ASSERT_TRUE(explained.has_value()) << "segment " << k;
        EXPECT_EQ(*explained, label) << "segment " << k;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            if (i != CYL3)
            {
                EXPECT_EQ(space_->objectPosition(b, i), space_->objectPosition(from_, i)) << "object " << i;
            }
        }
        if (label.kind != PrimitiveKind::Push)
        {
            EXPECT_FALSE(space_->objectMoves(a, b, CYL3)) << "segment " << k;
            continue;
        }
        ++pushes;
        EXPECT_EQ(label.object, static_cast<int>(CYL3));
        EXPECT_TRUE(validator().checkMotion(a, b))
            << "segment " << k << ": " << setup_->validityChecker()->explain(a) << " / "
            << setup_->validityChecker()->explain(b);
        // the tool moves on the straight line of the push, and keeps its place behind the object
        const Eigen::Vector3d lineStart = space_->toolPosition(a);
        for (unsigned int s = 0; s <= SAMPLES; ++s)
        {
            space_->interpolate(a, b, static_cast<double>(s) / SAMPLES, between);
            EXPECT_TRUE(setup_->getSpaceInformation()->isValid(between))
                << "segment " << k << " sample " << s;
            EXPECT_GE(space_->restingSurface(between, CYL3), 0);
            EXPECT_LE(distanceFromLine(space_->toolPosition(between), lineStart, direction),
                      2.0 * ArmPush::LINE_TOLERANCE);
            const Eigen::Isometry3d pose =
                push_->pushPose(CYL3, space_->objectPose(between, CYL3), direction.head<2>());
            EXPECT_LE((space_->toolPosition(between) - pose.translation()).norm(), ArmPush::LINE_TOLERANCE);
        }
    }
    space_->freeState(between);
    EXPECT_GE(pushes, 1u);
    // the whole offset, shorter than the longest push, is pushed; the object keeps its height
    const Eigen::Vector3d reached = space_->objectPosition(trajectory.back(), CYL3);
    EXPECT_NEAR((reached - space_->objectPosition(to_, CYL3)).norm(), 0.0, 1e-9);
    // the hand backs away from the object at the end, pushing nothing
    EXPECT_EQ(trajectory.label(trajectory.size() - 2).kind, PrimitiveKind::Transit);
}

TEST_P(ArmPushTest, PushesAtMostTheLongestPush)
{
    ASSERT_NE(push_, nullptr);
    pushCyl3By(DIAGONAL * 0.25, DIAGONAL * 0.25);
    Trajectory trajectory(space_);
    ASSERT_TRUE(propagate(trajectory));
    const Eigen::Vector3d moved =
        space_->objectPosition(trajectory.back(), CYL3) - space_->objectPosition(from_, CYL3);
    EXPECT_NEAR(moved.x(), DIAGONAL * MAX_PUSH, 1e-9);
    EXPECT_NEAR(moved.y(), DIAGONAL * MAX_PUSH, 1e-9);
    EXPECT_NEAR(moved.z(), 0.0, 1e-12);
}

TEST_P(ArmPushTest, ExplainsOnlyPushesThatKeepTheHandPose)
{
    ASSERT_NE(push_, nullptr);
    pushCyl3By(DIAGONAL * 0.08, DIAGONAL * 0.08);
    Trajectory trajectory(space_);
    ASSERT_TRUE(propagate(trajectory));
    std::size_t k = 0;
    while (trajectory.label(k).kind != PrimitiveKind::Push)
        ++k;
    ob::State *a = space_->cloneState(trajectory.state(k));
    ob::State *b = space_->cloneState(trajectory.state(k + 1));
    EXPECT_TRUE(push_->explain(a, b).has_value());
    EXPECT_FALSE(push_->explain(b, a).has_value()) << "pulling back along the line is no push";

    // the object pushed 1 cm beside the line the hand moves along
    ob::State *off = space_->cloneState(b);
    ObjectPose pose = space_->objectPose(b, CYL3);
    pose.position.x() += 0.01;
    space_->setObjectPose(off, CYL3, pose);
    EXPECT_FALSE(push_->explain(a, off).has_value());
    // another object moving as well
    pose = space_->objectPose(b, 0);
    pose.position.y() += 0.05;
    space_->setObjectPose(off, CYL3, space_->objectPose(b, CYL3));
    space_->setObjectPose(off, 0, pose);
    EXPECT_FALSE(push_->explain(a, off).has_value());
    // the object lifted off its surface
    space_->copyState(off, b);
    pose = space_->objectPose(b, CYL3);
    pose.position.z() += 0.01;
    space_->setObjectPose(off, CYL3, pose);
    EXPECT_FALSE(push_->explain(a, off).has_value());
    // the hand at its push pose at both ends, but reaching the end on another IK branch: the
    // joint motion between them swings the tool far off the line
    space_->copyState(off, b);
    Grasping arm(space_, Grasping::Settings{}, InverseKinematicsFactory());
    const Eigen::Isometry3d end = space_->model()->toolFrame(space_->robotValues(b));
    bool otherBranch = false;
    for (unsigned int attempt = 0; attempt < 50 && !otherBranch; ++attempt)
    {
        arm.randomizeChain(space_->robotValues(off));
        otherBranch = arm.solveToolPose(end, space_->robotValues(off)) &&
                      arm.jointDistance(space_->robotValues(off), space_->robotValues(b)) > 2.0;
    }
    ASSERT_TRUE(otherBranch);
    EXPECT_FALSE(push_->explain(a, off).has_value()) << "only the ends keep the push pose";
    space_->freeState(off);
    space_->freeState(a);
    space_->freeState(b);
}

INSTANTIATE_TEST_SUITE_P(KukaCabinet, ArmPushTest,
                         ::testing::Values("push_interior", "push_exterior", "push_frontal"));

TEST(ArmPushSettings, RejectsDistancesThatAreNotPositive)
{
    ompl_core::reseedOmpl(1);
    ManipulationSetup setup(loadScene(OMPL_MM_SCENES_DIR "/kuka_cabinet.xml"));
    const ManipulationStateSpace *space = setup.manipulationSpace().get();
    auto arm = std::make_shared<Grasping>(space, Grasping::Settings{}, InverseKinematicsFactory());
    for (auto broken : {&ArmPush::Settings::standoff, &ArmPush::Settings::maxPushDistance,
                        &ArmPush::Settings::maxPushJointDistance})
    {
        ArmPush::Settings settings;
        settings.*broken = 0.0;
        EXPECT_THROW(ArmPush(space, "push", arm, settings), ompl::Exception);
    }
    ArmPush::Settings settings;
    settings.approachDistance = -0.01;
    EXPECT_THROW(ArmPush(space, "push", arm, settings), ompl::Exception);
    settings.approachDistance = 0.0;
    EXPECT_NO_THROW(ArmPush(space, "push", arm, settings));
}

TEST(ArmPushOnMeka, PushesBottle1ToItsGoalAlongAStraightLine)
{
    // MEKA CLEAN-UP's bottle1 moves 0.058 m on the lower level: one push with the flat of the hand
    ompl_core::reseedOmpl(1);
    ManipulationSetup setup(loadScene(OMPL_MM_SCENES_DIR "/meka_cleanup.xml"));
    const ManipulationStateSpace *space = setup.manipulationSpace().get();
    const unsigned int bottle1 = 0;
    ob::State *from = space->cloneState(setup.getProblemDefinition()->getStartState(0));
    ob::State *to = space->cloneState(from);
    ObjectPose goal = space->objectPose(from, bottle1);
    goal.position.head<2>() = Eigen::Vector2d(0.13, -0.3);
    space->setObjectPose(to, bottle1, goal);
    Trajectory trajectory(space);
    bool pushed = false;
    for (const PrimitivePtr &primitive : setup.primitives())
        for (unsigned int attempt = 0;
             attempt < ATTEMPTS && !pushed && primitive->kind() == PrimitiveKind::Push; ++attempt)
        {
            trajectory.reset(from);
            pushed = primitive->propagate(from, to, trajectory);
        }
    ASSERT_TRUE(pushed);
    EXPECT_LE((space->objectPosition(trajectory.back(), bottle1) - goal.position).norm(), 1e-9);
    const auto &validator =
        static_cast<const ManipulationMotionValidator &>(*setup.getSpaceInformation()->getMotionValidator());
    unsigned int pushes = 0;
    for (std::size_t k = 0; k + 1 < trajectory.size(); ++k)
    {
        if (trajectory.label(k).kind != PrimitiveKind::Push)
            continue;
        ++pushes;
        const ob::State *a = trajectory.state(k);
        const ob::State *b = trajectory.state(k + 1);
        EXPECT_TRUE(validator.checkMotion(a, b)) << "segment " << k;
        ASSERT_TRUE(validator.explain(a, b).has_value());
        // the tool keeps its offset from the bottle within twice the line tolerance
        const Eigen::Vector3d offset = space->toolPosition(a) - space->objectPosition(a, bottle1);
        ob::State *between = space->allocState();
        for (unsigned int s = 0; s <= SAMPLES; ++s)
        {
            space->interpolate(a, b, static_cast<double>(s) / SAMPLES, between);
            EXPECT_LE(
                (space->toolPosition(between) - space->objectPosition(between, bottle1) - offset).norm(),
                2.0 * ArmPush::LINE_TOLERANCE);
        }
        space->freeState(between);
    }
    EXPECT_GE(pushes, 1u);
    space->freeState(from);
    space->freeState(to);
}
