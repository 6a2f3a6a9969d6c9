// Tests for PrimitiveFactory.
#include "ompl_mm/primitives/ArmPush.h"
#include "ompl_mm/primitives/PrimitiveFactory.h"
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mm/primitives/TransferRigid.h"
#include "ompl_mm/primitives/Transit.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    const ompl_core::SourceLocation WHERE{"unit_scene.xml", 17};

    PrimitiveSpec spec(const std::string &type, std::map<std::string, std::string> params = {})
    {
        return {type, std::move(params), WHERE};
    }

    /** A primitive type that applications might add: never useful, remembers its parameter. */
    class Wait : public Primitive
    {
    public:
        Wait(const ManipulationStateSpace *space, double seconds)
            : Primitive(space, "wait", PrimitiveKind::Transit), seconds_(seconds)
        {
        }
        bool isUseful(const ompl::base::State *, const ompl::base::State *) const override { return false; }
        bool propagate(const ompl::base::State *, const ompl::base::State *, Trajectory &) const override
        {
            return false;
        }
        std::optional<SegmentLabel> explain(const ompl::base::State *,
                                            const ompl::base::State *) const override
        {
            return std::nullopt;
        }
        double seconds() const { return seconds_; }

    private:
        double seconds_;
    };

    class Factory : public MobileBlockedTest
    {
    protected:
        /** The ompl_core::InputError message of building specs, or "" when it succeeds. */
        std::string error(const std::vector<PrimitiveSpec> &specs) const
        {
            return inputErrorOf([&] { factory_.build(specs, &space_); });
        }

        PrimitiveFactory factory_;
    };
}  // namespace

TEST_F(Factory, BuildsTheBuiltInTypes)
{
    const auto primitives =
        factory_.build({spec("transit"), spec("push_mobile", {{"standoff", "0.41"}})}, &space_);
    ASSERT_EQ(primitives.size(), 2u);
    EXPECT_TRUE(std::dynamic_pointer_cast<Transit>(primitives[0]));
    const auto push = std::dynamic_pointer_cast<PushMobile>(primitives[1]);
    ASSERT_TRUE(push);
    EXPECT_DOUBLE_EQ(push->standoff(0), 0.41);
    EXPECT_EQ(primitives[0]->name(), "transit");
    EXPECT_EQ(primitives[1]->kind(), PrimitiveKind::Push);
    EXPECT_TRUE(factory_.build({}, &space_).empty());
}

TEST_F(Factory, BuildsTheSceneFilePrimitives)
{
    const Scene scene = mobileBlockedScene();
    const auto primitives = factory_.build(scene.primitives, &space_);
    ASSERT_EQ(primitives.size(), 2u);
    EXPECT_EQ(primitives[0]->name(), "transit");
    EXPECT_EQ(primitives[1]->name(), "push_mobile");
}

TEST_F(Factory, UnknownTypeNamesTheLineAndTheKnownTypes)
{
    const std::string what = error({spec("transit"), spec("pick_and_place")});
    EXPECT_TRUE(startsWith(what, "unit_scene.xml:17: ")) << what;
    EXPECT_TRUE(contains(what, "pick_and_place")) << what;
    EXPECT_TRUE(contains(what, "push_mobile")) << what;
    EXPECT_TRUE(contains(what, "transit")) << what;
}

TEST_F(Factory, MissingStandoffIsComputedFromTheFootprints)
{
    const auto primitives = factory_.build({spec("push_mobile")}, &space_);
    EXPECT_DOUBLE_EQ(std::dynamic_pointer_cast<PushMobile>(primitives[0])->standoff(0), 0.41);
}

TEST_F(Factory, MalformedStandoffIsNamed)
{
    for (const char *value : {"abc", "nan", "inf", "0.4x", "", " "})
    {
        const std::string what = error({spec("push_mobile", {{"standoff", value}})});
        EXPECT_TRUE(startsWith(what, "unit_scene.xml:17: ")) << value << ": " << what;
        EXPECT_TRUE(contains(what, "'standoff'")) << what;
        EXPECT_TRUE(contains(what, std::string("'") + value + "'")) << what;
    }
}

TEST_F(Factory, NonPositiveStandoffIsReportedAtTheLine)
{
    for (const char *value : {"0", "-0.2"})
    {
        const std::string what = error({spec("push_mobile", {{"standoff", value}})});
        EXPECT_TRUE(startsWith(what, "unit_scene.xml:17: ")) << value << ": " << what;
        EXPECT_TRUE(contains(what, "standoff")) << what;
    }
}

TEST_F(Factory, UnknownParameterIsNamed)
{
    std::string what = error({spec("push_mobile", {{"standoff", "0.41"}, {"speed", "2"}})});
    EXPECT_TRUE(startsWith(what, "unit_scene.xml:17: ")) << what;
    EXPECT_TRUE(contains(what, "'speed'")) << what;
    what = error({spec("transit", {{"standoff", "0.41"}})});
    EXPECT_TRUE(contains(what, "'standoff'")) << what;
    EXPECT_TRUE(contains(what, "transit")) << what;
}

TEST_F(Factory, RegisteredTypesAreBuilt)
{
    factory_.registerType("wait", [](const ManipulationStateSpace *space, const PrimitiveParameters &params)
                          { return std::make_shared<Wait>(space, params.number("seconds", 1.5)); });
    auto primitives =
        factory_.build({spec("wait", {{"seconds", "2.5"}}), spec("wait"), spec("transit")}, &space_);
    ASSERT_EQ(primitives.size(), 3u);
    const auto wait = std::dynamic_pointer_cast<Wait>(primitives[0]);
    ASSERT_TRUE(wait);
    EXPECT_DOUBLE_EQ(wait->seconds(), 2.5);
    EXPECT_DOUBLE_EQ(std::dynamic_pointer_cast<Wait>(primitives[1])->seconds(), 1.5);  // the fallback
    // the registered type's parameters are checked like the built-in ones
    EXPECT_TRUE(contains(error({spec("wait", {{"seconds", "soon"}})}), "'seconds'"));
    EXPECT_TRUE(contains(error({spec("wait", {{"minutes", "1"}})}), "'minutes'"));
    // and it appears among the known types
    EXPECT_TRUE(contains(error({spec("fly")}), "wait"));

    // registering an existing name replaces its builder
    factory_.registerType("transit", [](const ManipulationStateSpace *space, const PrimitiveParameters &)
                          { return std::make_shared<Wait>(space, 0.0); });
    primitives = factory_.build({spec("transit")}, &space_);
    EXPECT_TRUE(std::dynamic_pointer_cast<Wait>(primitives[0]));
}

TEST_F(Factory, ParametersReadNumbers)
{
    const PrimitiveSpec s = spec("x", {{"a", "0.25"}, {"b", "1e-3"}, {"c", "oops"}});
    const PrimitiveParameters params(s);
    EXPECT_DOUBLE_EQ(params.number("a"), 0.25);
    EXPECT_DOUBLE_EQ(params.number("b", 7.0), 1e-3);
    EXPECT_DOUBLE_EQ(params.number("missing", 7.0), 7.0);
    EXPECT_THROW(params.number("missing"), ompl_core::InputError);
    EXPECT_THROW(params.number("c"), ompl_core::InputError);
    params.rejectUnread();  // all present names were asked for
    const PrimitiveParameters fresh(s);
    fresh.number("a");
    EXPECT_THROW(fresh.rejectUnread(), ompl_core::InputError);
}

TEST_F(Factory, MessagesNameTheLineTheTypeAndTheParameter)
{
    // the whole message of each check of the factory and of PrimitiveParameters
    EXPECT_EQ(
        error({spec("pick_and_place")}),
        "unit_scene.xml:17: unknown primitive <pick_and_place> (known: pickup, push_exterior, push_frontal, "
        "push_interior, push_mobile, transfer_rigid, transit)");
    EXPECT_EQ(error({spec("push_mobile", {{"standoff", "0.4x"}})}),
              "unit_scene.xml:17: <push_mobile> parameter 'standoff' must be a finite number, got '0.4x'");
    EXPECT_EQ(error({spec("push_mobile", {{"standoff", "0.41"}, {"speed", "2"}})}),
              "unit_scene.xml:17: unknown parameter 'speed' for <push_mobile>");
}

TEST_F(Factory, StandoffMustKeepRobotAndObjectApartAndTouchingIsAccepted)
{
    // PushMobile's own check, reported at the primitive's line with the value
    EXPECT_EQ(error({spec("push_mobile", {{"standoff", "0"}})}),
              "unit_scene.xml:17: push_mobile standoff must be positive, got 0.000000");
    EXPECT_EQ(error({spec("push_mobile", {{"standoff", "-0.2"}})}),
              "unit_scene.xml:17: push_mobile standoff must be positive, got -0.200000");
    EXPECT_TRUE(
        startsWith(error({spec("push_mobile", {{"standoff", "0.39"}})}),
                   "unit_scene.xml:17: push_mobile standoff 0.39 leaves the robot overlapping object"));
    const auto primitives = factory_.build({spec("push_mobile", {{"standoff", "0.4"}})}, &space_);
    ASSERT_EQ(primitives.size(), 1u);
    EXPECT_DOUBLE_EQ(std::dynamic_pointer_cast<PushMobile>(primitives[0])->standoff(0), 0.4);
}

TEST(PrimitiveFactoryRobot, PushMobileOnAnArmIsReportedAtItsLine)
{
    // push_mobile needs a planar base; the unit arm has one revolute joint
    ManipulationStateSpace space(makeModel(unitArmScene()));
    PrimitiveFactory factory;
    EXPECT_EQ(
        inputErrorOf(
            [&] {
                factory.build({spec("push_mobile", {{"standoff", "0.41"}})}, &space);
            }),
        "unit_scene.xml:17: push_mobile needs a robot whose base moves along world x and y (two prismatic "
        "joints)");
    EXPECT_EQ(factory.build({spec("transit")}, &space).size(), 1u);
}

TEST_F(Factory, ArmPushesReadTheirHandAndLimits)
{
    const std::vector<PrimitivePtr> primitives =
        factory_.build({spec("push_interior"),
                        spec("push_exterior", {{"standoff", "0.2"},
                                               {"height_offset", "-0.01"},
                                               {"downward_tilt", "40deg"},
                                               {"inward_tilt", "-15deg"},
                                               {"hand_roll", "90deg"},
                                               {"max_push_distance", "0.05"},
                                               {"max_push_joint_distance", "20deg"},
                                               {"approach_distance", "0"}}),
                        spec("push_frontal")},
                       &space_);
    ASSERT_EQ(primitives.size(), 3u);
    const auto interior = std::dynamic_pointer_cast<ArmPush>(primitives[0]);
    const auto exterior = std::dynamic_pointer_cast<ArmPush>(primitives[1]);
    const auto frontal = std::dynamic_pointer_cast<ArmPush>(primitives[2]);
    ASSERT_TRUE(interior && exterior && frontal);
    EXPECT_EQ(exterior->name(), "push_exterior");
    EXPECT_EQ(exterior->kind(), PrimitiveKind::Push);
    // the defaults: the hands of the KUKA scenes
    EXPECT_DOUBLE_EQ(interior->settings().standoff, 0.14);
    EXPECT_NEAR(interior->settings().downwardTilt, 65.0 * M_PI / 180.0, 1e-12);
    EXPECT_DOUBLE_EQ(interior->settings().handRoll, 0.0);
    EXPECT_NEAR(frontal->settings().handRoll, 0.0, 1e-12);
    EXPECT_NEAR(frontal->settings().inwardTilt, 30.0 * M_PI / 180.0, 1e-12);
    EXPECT_DOUBLE_EQ(frontal->settings().downwardTilt, 0.0);
    EXPECT_DOUBLE_EQ(interior->settings().maxPushDistance, 0.1);
    EXPECT_NEAR(interior->settings().maxPushJointDistance, 30.0 * M_PI / 180.0, 1e-4);
    // the values given
    EXPECT_DOUBLE_EQ(exterior->settings().standoff, 0.2);
    EXPECT_DOUBLE_EQ(exterior->settings().heightOffset, -0.01);
    EXPECT_NEAR(exterior->settings().downwardTilt, 40.0 * M_PI / 180.0, 1e-12);
    EXPECT_NEAR(exterior->settings().inwardTilt, -15.0 * M_PI / 180.0, 1e-12);
    EXPECT_NEAR(exterior->settings().handRoll, 0.5 * M_PI, 1e-12);
    EXPECT_DOUBLE_EQ(exterior->settings().maxPushDistance, 0.05);
    EXPECT_NEAR(exterior->settings().maxPushJointDistance, 20.0 * M_PI / 180.0, 1e-12);
    EXPECT_DOUBLE_EQ(exterior->settings().approachDistance, 0.0);
}

TEST_F(Factory, ArmPushErrorsNameTheLine)
{
    EXPECT_EQ(error({spec("push_interior", {{"standoff", "0"}})}),
              "unit_scene.xml:17: push_interior standoff must be positive, got 0.000000");
    EXPECT_EQ(error({spec("push_frontal", {{"max_push_distance", "-0.1"}})}),
              "unit_scene.xml:17: push_frontal max_push_distance must be positive, got -0.100000");
    EXPECT_EQ(error({spec("push_exterior", {{"approach_distance", "-1"}})}),
              "unit_scene.xml:17: the approach distance must be at least 0, got -1.000000");
    EXPECT_EQ(error({spec("push_exterior", {{"downward_tilt", "steep"}})}),
              "unit_scene.xml:17: <push_exterior> parameter 'downward_tilt' must be an angle (radians, or "
              "degrees as in 45deg), got 'steep'");
    EXPECT_EQ(error({spec("push_interior", {{"ik_any_yaw", "yes"}})}),
              "unit_scene.xml:17: <push_interior> parameter 'ik_any_yaw' must be true or false, got 'yes'");
    EXPECT_EQ(error({spec("push_interior", {{"push_length", "0.1"}})}),
              "unit_scene.xml:17: unknown parameter 'push_length' for <push_interior>");
}

TEST_F(Factory, TransferReadsItsPlaceHeight)
{
    const std::vector<PrimitivePtr> primitives =
        factory_.build({spec("transfer_rigid"), spec("transfer_rigid", {{"place_height", "0.05"}})}, &space_);
    ASSERT_EQ(primitives.size(), 2u);
    const auto straight = std::dynamic_pointer_cast<TransferRigid>(primitives[0]);
    const auto fromAbove = std::dynamic_pointer_cast<TransferRigid>(primitives[1]);
    ASSERT_TRUE(straight && fromAbove);
    EXPECT_EQ(straight->placeHeight(), 0.0);
    EXPECT_EQ(fromAbove->placeHeight(), 0.05);
    EXPECT_EQ(error({spec("transfer_rigid", {{"place_height", "-0.05"}})}),
              "unit_scene.xml:17: transfer_rigid place_height must be at least 0, got -0.050000");
    EXPECT_EQ(error({spec("transfer_rigid", {{"place_height", "high"}})}),
              "unit_scene.xml:17: <transfer_rigid> parameter 'place_height' must be a finite number, got "
              "'high'");
}
