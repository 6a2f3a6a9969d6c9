// Tests for PhysicsPush and physicsPrimitiveFactory().
#include "ompl_mmphys/primitives/PhysicsPush.h"

#include "common/MobileBlocked.h"
#include "ompl_mm/primitives/EmptySpacePlanner.h"
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mm/primitives/Transit.h"
#include "ompl_mmphys/primitives/PhysicsPrimitives.h"
#include "ompl_mmphys/simulation/PlanSimulation.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;
using ompl_mmphys::PhysicsPush;

namespace
{
    constexpr unsigned int OBJ3 = 2;

    /** MOBILE BLOCKED with a physics-aware push of its own; obj3's target is its goal. */
    class PhysicsPushTest : public MobileBlockedTest
    {
    protected:
        PhysicsPushTest()
        {
            push_->setStateValidityChecker(setup_.getStateValidityChecker());
            setRobot(space_, start_, -2.1, -2.1);  // the way behind obj3 is free
            setRobot(space_, target_, -2.1, -2.1);
            ObjectPose goal = space_.objectPose(start_, OBJ3);
            goal.position.head<2>() = Eigen::Vector2d(-0.9, -0.9);
            space_.setObjectPose(target_, OBJ3, goal);
        }

        /** The trajectory as a path. */
        ManipulationPath pathOf(const Trajectory &trajectory) const
        {
            ManipulationPath path(setup_.getSpaceInformation());
            path.appendFirst(trajectory.state(0));
            for (std::size_t i = 1; i < trajectory.size(); ++i)
                path.appendLabelled(trajectory.state(i), trajectory.label(i - 1));
            return path;
        }

        /** Pushes obj3 from start_ towards target_. */
        Trajectory pushObj3()
        {
            Trajectory trajectory(&space_);
            trajectory.reset(start_);
            EXPECT_TRUE(push_->propagate(start_, target_, trajectory)) << push_->takeRejection();
            return trajectory;
        }

        std::shared_ptr<PushMobile> kinematic_ = std::make_shared<PushMobile>(&space_, STANDOFF);
        std::shared_ptr<PhysicsPush> push_ = std::make_shared<PhysicsPush>(
            &space_, kinematic_, [](unsigned int) { return STANDOFF; }, PhysicsPush::Settings());
        ompl::base::State *start_ = startCopy();
        ompl::base::State *target_ = startCopy();
    };
}  // namespace

TEST_F(PhysicsPushTest, PushesUntilTheObjectIsWithinThePrecisionOfItsTarget)
{
    const Trajectory trajectory = pushObj3();
    const Eigen::Vector3d reached = space_.objectPosition(trajectory.back(), OBJ3);
    EXPECT_LT((reached - space_.objectPosition(target_, OBJ3)).head<2>().norm(), 0.005);
    EXPECT_GT(push_->simulations(), 1u) << "re-aimed along the way";
    EXPECT_GT(push_->simulationTime(), 0.0);
    EXPECT_FALSE(push_->endsWhereAsked());
    EXPECT_EQ(push_->kinematicModel(), kinematic_);
    // the other objects stay where they were
    for (unsigned int k = 0; k < space_.objectCount(); ++k)
        EXPECT_TRUE(k == OBJ3 || !space_.objectMoves(start_, trajectory.back(), k)) << "object " << k;
}

TEST_F(PhysicsPushTest, TheWholePlanSimulationEndsEachPushWhereThePushPutItsObject)
{
    const Trajectory trajectory = pushObj3();
    const ompl_mmphys::SimulatedPlan simulated = ompl_mmphys::simulatePlan(pathOf(trajectory));
    std::size_t compared = 0;
    for (std::size_t i = 1; i < trajectory.size(); ++i)
        if (trajectory.label(i - 1).kind == PrimitiveKind::Push && trajectory.branchable(i))
        {
            // measured: within 1.1 mm
            EXPECT_LT(
                (simulated.statePoses[i][OBJ3].position - space_.objectPosition(trajectory.state(i), OBJ3))
                    .head<2>()
                    .norm(),
                0.003)
                << "after the push ending at waypoint " << i;
            ++compared;
        }
    EXPECT_GT(compared, 1u);
}

TEST_F(PhysicsPushTest, APushEndsWithTheObjectExactlyWhereTheSimulationLeftIt)
{
    // backing away 1 mm only, the disc stays closer than the standoff (the pushed cylinder rests
    // 0.40 m from the tool point, the standoff is 0.41 m): the end must not be moved to the
    // standoff, or the next motion would start 1 cm from where physics has the object
    PhysicsPush::Settings settings;
    settings.retreat = 0.001;
    const auto close = std::make_shared<PhysicsPush>(
        &space_, kinematic_, [](unsigned int) { return STANDOFF; }, settings);
    Trajectory trajectory(&space_);
    trajectory.reset(start_);
    ASSERT_TRUE(close->propagate(start_, target_, trajectory)) << close->takeRejection();
    const ompl_mmphys::SimulatedPlan simulated = ompl_mmphys::simulatePlan(pathOf(trajectory));
    std::size_t ends = 0;
    for (std::size_t i = 1; i < trajectory.size(); ++i)
        if (trajectory.label(i - 1).kind == PrimitiveKind::Push && trajectory.branchable(i))
        {
            const Eigen::Vector3d planned = space_.objectPosition(trajectory.state(i), OBJ3);
            EXPECT_LT((space_.toolPosition(trajectory.state(i)) - planned).head<2>().norm(), STANDOFF)
                << "the tool stays close at waypoint " << i;
            EXPECT_LT((simulated.statePoses[i][OBJ3].position - planned).head<2>().norm(), 0.003)
                << "after the push ending at waypoint " << i;
            ++ends;
        }
    EXPECT_GT(ends, 0u);
}

TEST(PhysicsPushRocking, APushThatRocksItsObjectFailsThoughItEndsUpright)
{
    // obj3 a box 0.2 x 0.2 x 0.6 m: the disc's push rocks it beyond 10 degrees, and it settles
    // back upright (measured: boxes 0.1 and 0.15 m wide tip over, 0.25 m wide stay upright)
    Scene scene = mobileBlockedScene();
    scene.objects[OBJ3].shape.kind = Shape::Kind::Box;
    scene.objects[OBJ3].shape.boxSize = Eigen::Vector3d(0.2, 0.2, 0.6);
    ManipulationSetup setup(scene);
    const ManipulationStateSpace &space = *setup.manipulationSpace();
    ompl::base::State *start = space.cloneState(setup.getProblemDefinition()->getStartState(0));
    setRobot(space, start, -2.1, -2.1);
    ompl::base::State *target = space.cloneState(start);
    ObjectPose goal = space.objectPose(start, OBJ3);
    goal.position.head<2>() = Eigen::Vector2d(-0.9, -0.9);
    space.setObjectPose(target, OBJ3, goal);
    const auto pushWith = [&](const PhysicsPush::Settings &settings, std::string &rejection)
    {
        PhysicsPush push(
            &space, std::make_shared<PushMobile>(&space, STANDOFF), [](unsigned int) { return STANDOFF; },
            settings);
        Trajectory trajectory(&space);
        trajectory.reset(start);
        const bool pushed = push.propagate(start, target, trajectory);
        rejection = push.takeRejection();
        return pushed;
    };
    std::string rejection;
    EXPECT_FALSE(pushWith(PhysicsPush::Settings(), rejection));
    EXPECT_EQ(rejection, "the push rocks object 'obj3' (more than 10 degrees from upright)");
    PhysicsPush::Settings lenient;
    lenient.rock = M_PI / 4.0;
    EXPECT_TRUE(pushWith(lenient, rejection)) << rejection;
    space.freeState(start);
    space.freeState(target);
}

TEST_F(PhysicsPushTest, APushEndsBeforeItsObjectSlidesAroundThePusher)
{
    // pushed off the diagonal, obj3 slides around the disc's rim; with a tight slip limit each
    // push ends before the object leaves it, and is corrected from there
    ObjectPose aside = space_.objectPose(start_, OBJ3);
    aside.position.head<2>() = Eigen::Vector2d(-0.3, -1.1);
    space_.setObjectPose(target_, OBJ3, aside);
    PhysicsPush::Settings settings;
    settings.slip = 0.1;
    settings.corrections = 20;
    const auto tight = std::make_shared<PhysicsPush>(
        &space_, kinematic_, [](unsigned int) { return STANDOFF; }, settings);
    tight->setStateValidityChecker(setup_.getStateValidityChecker());
    Trajectory trajectory(&space_);
    trajectory.reset(start_);
    ASSERT_TRUE(tight->propagate(start_, target_, trajectory)) << tight->takeRejection();
    std::size_t checked = 0;
    for (std::size_t i = 1; i + 1 < trajectory.size(); ++i)
        if (trajectory.label(i - 1).kind == PrimitiveKind::Push && !trajectory.branchable(i))
        {  // pushing, not yet backed away: the object lies within the limit of the tool's heading
            const Eigen::Vector2d tool = space_.toolPosition(trajectory.state(i)).head<2>();
            const Eigen::Vector2d heading = tool - space_.toolPosition(trajectory.state(i - 1)).head<2>();
            const Eigen::Vector2d toObject =
                space_.objectPosition(trajectory.state(i), OBJ3).head<2>() - tool;
            EXPECT_LE(std::acos(heading.normalized().dot(toObject.normalized())), settings.slip + 1e-9)
                << "waypoint " << i;
            ++checked;
        }
    EXPECT_GT(checked, 3u);
    const Trajectory loose = pushObj3();
    EXPECT_GT(tight->simulations(), push_->simulations()) << "pushes ended early and were corrected";
}

TEST_F(PhysicsPushTest, OnlyTheEndOfAPushAfterTheToolBacksAwayIsBranchable)
{
    const Trajectory trajectory = pushObj3();
    for (std::size_t i = 1; i < trajectory.size(); ++i)
    {
        const bool pushEnds = trajectory.label(i - 1).kind == PrimitiveKind::Push &&
                              (i + 1 == trajectory.size() || trajectory.label(i).kind != PrimitiveKind::Push);
        const bool pushes = trajectory.label(i - 1).kind == PrimitiveKind::Push;
        EXPECT_EQ(trajectory.branchable(i), !pushes || pushEnds) << "waypoint " << i;
    }
}

TEST_F(PhysicsPushTest, ExplainsItsOwnSegmentsAndTheirPiecesOnly)
{
    const Trajectory trajectory = pushObj3();
    std::size_t push = 0;
    while (trajectory.label(push).kind != PrimitiveKind::Push)
        ++push;
    const std::optional<SegmentLabel> label =
        push_->explain(trajectory.state(push), trajectory.state(push + 1));
    ASSERT_TRUE(label);
    EXPECT_EQ(*label, (SegmentLabel{PrimitiveKind::Push, static_cast<int>(OBJ3)}));
    ompl::base::State *a = newState();
    ompl::base::State *b = newState();
    space_.interpolate(trajectory.state(push), trajectory.state(push + 1), 0.25, a);
    space_.interpolate(trajectory.state(push), trajectory.state(push + 1), 0.75, b);
    EXPECT_TRUE(push_->explain(a, b));
    EXPECT_FALSE(push_->explain(b, a)) << "backwards";
    // a kinematic push of the same object that it did not make
    Trajectory other(&space_);
    other.reset(start_);
    ASSERT_TRUE(kinematic_->propagate(start_, target_, other));
    EXPECT_TRUE(kinematic_->explain(other.state(other.size() - 2), other.back()));
    EXPECT_FALSE(push_->explain(other.state(other.size() - 2), other.back()));
}

TEST_F(PhysicsPushTest, ABlockedWayToThePushStartIsWalkedButNotSimulated)
{
    setRobot(space_, start_, 1.9, 1.9);  // the blocks stand between the robot and obj3
    Trajectory trajectory(&space_);
    trajectory.reset(start_);
    ASSERT_TRUE(push_->propagate(start_, target_, trajectory));
    EXPECT_EQ(push_->simulations(), 0u);
    for (std::size_t i = 0; i + 1 < trajectory.size(); ++i)
        EXPECT_EQ(trajectory.label(i).kind, PrimitiveKind::Transit);
    EXPECT_FALSE(space_.anyObjectMoves(start_, trajectory.back()));
}

TEST_F(PhysicsPushTest, TheSameStartGivesTheSamePush)
{
    const Trajectory first = pushObj3();
    const Trajectory second = pushObj3();
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i)
        EXPECT_TRUE(space_.equalStates(first.state(i), second.state(i))) << "waypoint " << i;
}

TEST_F(PhysicsPushTest, TheEmptySpacePlannerGoesOnFromWhereThePushLeftTheObject)
{
    EmptySpacePlanner esp(&space_, {std::make_shared<Transit>(&space_), push_});
    setRobot(space_, target_, -2.0, -1.2);
    Trajectory trajectory(&space_);
    ompl::RNG rng(3);
    EXPECT_EQ(esp.plan(start_, target_, trajectory, rng), EmptySpacePlanner::Outcome::Partial);
    EXPECT_EQ(space_.robotValues(trajectory.back())[0], -2.0);
    EXPECT_EQ(space_.robotValues(trajectory.back())[1], -1.2);
    EXPECT_EQ(trajectory.label(trajectory.size() - 2).kind, PrimitiveKind::Transit);
    // the goal tree's planner leaves simulated primitives out
    EXPECT_EQ(esp.plan(start_, target_, trajectory, rng, ompl::base::plannerNonTerminatingCondition(), true),
              EmptySpacePlanner::Outcome::Failed);
}

TEST_F(PhysicsPushTest, BadSettingsAreRefused)
{
    PhysicsPush::Settings settings;
    settings.precision = 0.0;
    EXPECT_THROW(PhysicsPush(
                     &space_, kinematic_, [](unsigned int) { return STANDOFF; }, settings),
                 ompl::Exception);
    settings = {};
    settings.rock = -1.0;
    EXPECT_THROW(PhysicsPush(
                     &space_, kinematic_, [](unsigned int) { return STANDOFF; }, settings),
                 ompl::Exception);
    settings = {};
    settings.slip = 0.0;
    EXPECT_THROW(PhysicsPush(
                     &space_, kinematic_, [](unsigned int) { return STANDOFF; }, settings),
                 ompl::Exception);
    settings = {};
    settings.simulation.timeStep = -1.0;
    EXPECT_THROW(PhysicsPush(
                     &space_, kinematic_, [](unsigned int) { return STANDOFF; }, settings),
                 ompl::Exception);
}

namespace
{
    const ompl_core::SourceLocation WHERE{"unit_scene.xml", 12};

    /** The InputError message of building one primitive with factory, or "" when it builds. */
    std::string buildError(const PrimitiveFactory &factory, const ManipulationStateSpace &space,
                           std::map<std::string, std::string> params, const std::string &type = "push_mobile")
    {
        return inputErrorOf([&] { factory.build({{type, std::move(params), WHERE}}, &space); });
    }
}  // namespace

TEST_F(PhysicsPushTest, TheModelAttributeChoosesThePush)
{
    const PrimitiveFactory factory = ompl_mmphys::physicsPrimitiveFactory();
    const auto built = [&](std::map<std::string, std::string> params) {
        return factory.build({{"push_mobile", std::move(params), WHERE}}, &space_).front();
    };
    EXPECT_TRUE(std::dynamic_pointer_cast<PushMobile>(built({})));
    EXPECT_TRUE(std::dynamic_pointer_cast<PushMobile>(built({{"model", "kinematic"}})));
    const PrimitivePtr physics =
        built({{"model", "physics"}, {"standoff", "0.41"}, {"push_precision", "0.002"}});
    ASSERT_TRUE(std::dynamic_pointer_cast<PhysicsPush>(physics));
    EXPECT_EQ(physics->name(), "push_mobile");
    EXPECT_EQ(physics->kind(), PrimitiveKind::Push);
}

TEST_F(PhysicsPushTest, ModelErrorsNameTheLine)
{
    const PrimitiveFactory physics = ompl_mmphys::physicsPrimitiveFactory();
    EXPECT_TRUE(startsWith(buildError(physics, space_, {{"model", "exact"}}), "unit_scene.xml:12: "));
    EXPECT_TRUE(contains(buildError(physics, space_, {{"model", "exact"}}), "must be kinematic or physics"));
    EXPECT_TRUE(contains(buildError(physics, space_, {{"model", "physics"}, {"push_precision", "0"}}),
                         "'push_precision' must be positive"));
    EXPECT_TRUE(contains(buildError(physics, space_, {{"model", "physics"}, {"push_corrections", "21"}}),
                         "'push_corrections'"));
    EXPECT_TRUE(contains(buildError(physics, space_, {{"model", "physics"}, {"standof", "0.41"}}),
                         "unknown parameter 'standof'"));
    // ompl_mm's own factory cannot simulate, and says where that is done
    EXPECT_TRUE(contains(buildError(PrimitiveFactory(), space_, {{"model", "physics"}}),
                         "physicsPrimitiveFactory()"));
    EXPECT_TRUE(startsWith(buildError(PrimitiveFactory(), space_, {{"model", "physics"}}, "push_frontal"),
                           "unit_scene.xml:12: "));
}
