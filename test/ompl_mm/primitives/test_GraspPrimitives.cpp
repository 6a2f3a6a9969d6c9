// Tests for Pickup, TransferRigid and Grasping.
#include "ompl_mm/primitives/EmptySpacePlanner.h"
#include "ompl_mm/primitives/Grasping.h"
#include "ompl_mm/primitives/Pickup.h"
#include "ompl_mm/primitives/TransferRigid.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <gtest/gtest.h>

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace ompl_mm;
namespace ob = ompl::base;
using Outcome = EmptySpacePlanner::Outcome;

namespace
{
    /** The objects of KUKA TABLE the tests move or disturb. */
    constexpr unsigned int CYL1 = 0, CYL2 = 1;
    /** KUKA TABLE's pickup lift height, grasp tilt and approach distance. */
    constexpr double LIFT = 0.10;
    const double TILT = 45.0 * M_PI / 180.0;
    constexpr double APPROACH = 0.05;
    /** Half the length of a cylinder: its centre above its base. */
    constexpr double HALF_LENGTH = 0.05;
    /** Where the tests place cyl1 on table 2 (the scene's goal for it). */
    const Eigen::Vector3d ON_TABLE2{0.18, -0.5, 0.43};
    /** Index of table 2 among the scene's support surfaces. */
    constexpr int TABLE2 = 1;
    /** Tolerance of the poses reached by inverse kinematics (the grasp tolerance). */
    constexpr double IK_TOL = 1e-4;
    /** The seed of OMPL's random numbers for the fixture (the grasp IK draws random restarts). */
    constexpr std::uint_fast32_t SEED = 1;

    const SegmentLabel TRANSIT{PrimitiveKind::Transit, -1};
    const SegmentLabel PICKUP_CYL1{PrimitiveKind::Pickup, static_cast<int>(CYL1)};
    const SegmentLabel TRANSFER_CYL1{PrimitiveKind::Transfer, static_cast<int>(CYL1)};

    /** The KUKA TABLE scene, loaded from scenes/kuka_table.xml. */
    Scene kukaTableScene()
    {
        return loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml");
    }

    /** Seeds OMPL's random numbers (RNGs made from now on), without the error OMPL logs when some
        were made before. */
    void seedOmpl(std::uint_fast32_t seed)
    {
        const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
        ompl::RNG::setSeed(seed);
        ompl::msg::setLogLevel(level);
    }

    /** KUKA TABLE's setup, made after seeding OMPL's random numbers with seed; its transfer
        places from placeHeight above the place when that is given. */
    ManipulationSetup seededSetup(std::uint_fast32_t seed, const std::string &placeHeight = "")
    {
        seedOmpl(seed);
        Scene scene = kukaTableScene();
        for (PrimitiveSpec &spec : scene.primitives)
            if (spec.type == "transfer_rigid" && !placeHeight.empty())
                spec.params["place_height"] = placeHeight;
        return ManipulationSetup(scene);
    }

    /** The setup's primitive called name, as a P, or null. */
    template <class P>
    std::shared_ptr<P> primitiveOf(const ManipulationSetup &setup, const std::string &name)
    {
        for (const PrimitivePtr &primitive : setup.primitives())
            if (primitive->name() == name)
                return std::dynamic_pointer_cast<P>(primitive);
        return nullptr;
    }

    /** The tool frame at state's joints. */
    Eigen::Isometry3d toolFrameOf(const ManipulationStateSpace &space, const ob::State *state)
    {
        return space.model()->toolFrame(space.robotValues(state));
    }

    /** The tool's approach axis (its z) in the world at state's joints. */
    Eigen::Vector3d approachAxis(const ManipulationStateSpace &space, const ob::State *state)
    {
        return toolFrameOf(space, state).linear().col(2);
    }

    /** The object's base centre in the tool frame of state. */
    Eigen::Vector3d inTool(const ManipulationStateSpace &space, const ob::State *state, unsigned int object)
    {
        return toolFrameOf(space, state).inverse() * space.objectPosition(state, object);
    }

    /** True when the object rests on no support surface in state. */
    bool held(const ManipulationStateSpace &space, const ob::State *state, unsigned int object)
    {
        return space.restingSurface(state, object) < 0;
    }

    /** Every object but `object` has exactly its pose of `reference` in every waypoint. */
    void expectOthersKeepTheirPoses(const ManipulationStateSpace &space, const Trajectory &trajectory,
                                    const ob::State *reference, unsigned int object)
    {
        for (std::size_t k = 0; k < trajectory.size(); ++k)
            for (unsigned int i = 0; i < space.objectCount(); ++i)
                if (i != object)
                {
                    EXPECT_EQ(space.objectPosition(trajectory.state(k), i),
                              space.objectPosition(reference, i))
                        << "object " << i << " waypoint " << k;
                    EXPECT_EQ(space.objectYaw(trajectory.state(k), i), space.objectYaw(reference, i))
                        << "object " << i << " waypoint " << k;
                }
    }

    /** Every waypoint has the robot within its joint limits (what inverse kinematics promises). */
    void expectWithinJointLimits(const ManipulationStateSpace &space, const Trajectory &trajectory)
    {
        for (std::size_t k = 0; k < trajectory.size(); ++k)
            EXPECT_TRUE(space.satisfiesBounds(trajectory.state(k))) << "waypoint " << k;
    }

    /** KUKA TABLE made with a seed: its setup, start, pickup and transfer, the target with cyl1 on
        table 2, and states made from them (freed with it). */
    struct KukaTable
    {
        explicit KukaTable(std::uint_fast32_t seed, const std::string &placeHeight = "")
            : setup(seededSetup(seed, placeHeight)),
              space(*setup.manipulationSpace()),
              start(setup.getProblemDefinition()->getStartState(0)),
              pickup(primitiveOf<Pickup>(setup, "pickup")),
              transfer(primitiveOf<TransferRigid>(setup, "transfer_rigid")),
              target(withObject(start, CYL1, {ON_TABLE2, 0.0}))
        {
        }

        ~KukaTable()
        {
            for (ob::State *state : owned)
                space.freeState(state);
        }

        KukaTable(const KukaTable &) = delete;
        KukaTable &operator=(const KukaTable &) = delete;

        /** A copy of state with the object at pose. */
        ob::State *withObject(const ob::State *state, unsigned int object, const ObjectPose &pose)
        {
            ob::State *copy = space.cloneState(state);
            owned.push_back(copy);
            space.setObjectPose(copy, object, pose);
            return copy;
        }

        /** The pickup from the start towards target, into trajectory; false when it fails. */
        bool pickUp(Trajectory &trajectory) const
        {
            trajectory.reset(start);
            return pickup->propagate(start, target, trajectory);
        }

        /** The transfer from `from` towards `to`, into trajectory; false when it fails. */
        bool carry(const ob::State *from, const ob::State *to, Trajectory &trajectory) const
        {
            trajectory.reset(from);
            return transfer->propagate(from, to, trajectory);
        }

        std::vector<ob::State *> owned;  // first: the others' initialisers use it
        ManipulationSetup setup;
        const ManipulationStateSpace &space;
        const ob::State *start;
        std::shared_ptr<Pickup> pickup;
        std::shared_ptr<TransferRigid> transfer;
        ob::State *target;
    };

    class KukaGrasp : public ::testing::Test, public KukaTable
    {
    protected:
        KukaGrasp() : KukaTable(SEED) {}

        void SetUp() override
        {
            ASSERT_TRUE(pickup);
            ASSERT_TRUE(transfer);
        }
    };
}  // namespace

TEST_F(KukaGrasp, SceneHasThePrimitivesAndSettings)
{
    EXPECT_DOUBLE_EQ(pickup->settings().liftHeight, LIFT);
    EXPECT_DOUBLE_EQ(pickup->settings().minPlaneDistance, 0.2);
    EXPECT_EQ(pickup->kind(), PrimitiveKind::Pickup);
    EXPECT_EQ(transfer->kind(), PrimitiveKind::Transfer);
    // every object rests at the start
    for (unsigned int i = 0; i < space.objectCount(); ++i)
        EXPECT_FALSE(held(space, start, i)) << "object " << i;
}

TEST_F(KukaGrasp, PickupIsUsefulOnlyForALongMoveFromRest)
{
    EXPECT_TRUE(pickup->isUseful(start, target));
    // nothing to rise for when the target is the start
    EXPECT_FALSE(pickup->isUseful(start, start));
    // 0.1 m in the plane at the same height: below min_plane_distance
    const Eigen::Vector3d at = space.objectPosition(start, CYL1);
    EXPECT_FALSE(
        pickup->isUseful(start, withObject(start, CYL1, {at + Eigen::Vector3d(0.1, 0.0, 0.0), 0.0})));
    EXPECT_FALSE(
        pickup->isUseful(start, withObject(start, CYL1, {at + Eigen::Vector3d(0.0, -0.1, 0.0), 0.0})));
    // 0.25 m in the plane is beyond it
    EXPECT_TRUE(
        pickup->isUseful(start, withObject(start, CYL1, {at + Eigen::Vector3d(0.0, -0.25, 0.0), 0.0})));
    // held in the target: it must rise
    EXPECT_TRUE(pickup->isUseful(start, withObject(start, CYL1, {at + Eigen::Vector3d(0.0, 0.0, 0.2), 0.0})));
    // an object held (off every surface) in `from`: no pickup
    ob::State *holding =
        withObject(start, CYL2, {space.objectPosition(start, CYL2) + Eigen::Vector3d(0.0, 0.0, 0.1), 0.0});
    ASSERT_TRUE(held(space, holding, CYL2));
    EXPECT_FALSE(pickup->isUseful(holding, target));
}

TEST_F(KukaGrasp, PickupGraspsFromAboveAndLiftsByTheLiftHeight)
{
    Trajectory trajectory(&space);
    ASSERT_TRUE(pickUp(trajectory));
    ASSERT_GE(trajectory.size(), 3u);  // start, (approach,) grasp, lift
    ASSERT_LE(trajectory.size(), 4u);
    EXPECT_TRUE(space.equalStates(trajectory.state(0), start));
    const std::size_t last = trajectory.size() - 1;
    EXPECT_EQ(trajectory.label(last - 1), PICKUP_CYL1);
    for (std::size_t k = 0; k + 1 < last; ++k)
        EXPECT_EQ(trajectory.label(k), TRANSIT) << "segment " << k;
    expectWithinJointLimits(space, trajectory);
    expectOthersKeepTheirPoses(space, trajectory, start, CYL1);

    // cyl1 stays until the lift, then is lifted straight up by the lift height, off every surface
    const Eigen::Vector3d base = space.objectPosition(start, CYL1);
    for (std::size_t k = 0; k < last; ++k)
        EXPECT_EQ(space.objectPosition(trajectory.state(k), CYL1), base) << "waypoint " << k;
    const Eigen::Vector3d lifted = space.objectPosition(trajectory.back(), CYL1);
    EXPECT_NEAR(lifted.z(), 0.53, IK_TOL);
    EXPECT_NEAR(lifted.z() - base.z(), LIFT, IK_TOL);
    EXPECT_NEAR(lifted.x(), base.x(), IK_TOL);
    EXPECT_NEAR(lifted.y(), base.y(), IK_TOL);
    EXPECT_TRUE(held(space, trajectory.back(), CYL1));

    // the grasp: the tool point at cyl1's centre, the approach axis down at the grasp tilt
    const ob::State *grasp = trajectory.state(last - 1);
    const Eigen::Vector3d centre = base + Eigen::Vector3d(0.0, 0.0, HALF_LENGTH);
    EXPECT_LE((space.toolPosition(grasp) - centre).norm(), IK_TOL)
        << "tool " << space.toolPosition(grasp).transpose() << " centre " << centre.transpose();
    const Eigen::Vector3d axis = approachAxis(space, grasp);
    EXPECT_NEAR(axis.z(), -std::cos(TILT), IK_TOL) << axis.transpose();
    EXPECT_NEAR(axis.head<2>().norm(), std::sin(TILT), IK_TOL) << axis.transpose();

    // the approach (when the robot is not there already) is the approach distance back along it
    if (trajectory.size() == 4u)
    {
        const ob::State *approach = trajectory.state(1);
        EXPECT_LE((space.toolPosition(approach) - (centre - APPROACH * axis)).norm(), IK_TOL);
        EXPECT_LE((approachAxis(space, approach) - axis).norm(), IK_TOL);
    }

    // the object is held in the lift as it was grasped, and the tool keeps its orientation
    EXPECT_TRUE(Grasping::sameGrasp(space, grasp, trajectory.back(), CYL1));
    EXPECT_LE((inTool(space, grasp, CYL1) - inTool(space, trajectory.back(), CYL1)).norm(),
              Grasping::GRASP_TOLERANCE);
    EXPECT_LE((approachAxis(space, trajectory.back()) - axis).norm(), IK_TOL);
}

TEST_F(KukaGrasp, PickupExplainsTheLiftOnly)
{
    Trajectory trajectory(&space);
    ASSERT_TRUE(pickUp(trajectory));
    const ob::State *grasp = trajectory.state(trajectory.size() - 2);
    const ob::State *lifted = trajectory.back();
    const auto lift = pickup->explain(grasp, lifted);
    ASSERT_TRUE(lift.has_value());
    EXPECT_EQ(*lift, PICKUP_CYL1);

    // a robot-only move is no pickup
    EXPECT_FALSE(pickup->explain(start, grasp).has_value());
    // nor a lift in which another object moves too
    ob::State *both =
        withObject(lifted, CYL2, {space.objectPosition(start, CYL2) + Eigen::Vector3d(0.05, 0.0, 0.0), 0.0});
    EXPECT_FALSE(pickup->explain(grasp, both).has_value());
    // nor one in which the object does not keep its grasp
    ob::State *slipped =
        withObject(lifted, CYL1, {space.objectPosition(lifted, CYL1) + Eigen::Vector3d(0.0, 0.0, 0.02), 0.0});
    EXPECT_FALSE(pickup->explain(grasp, slipped).has_value());
    // nor a move from a state where the object is already held
    EXPECT_FALSE(pickup->explain(lifted, grasp).has_value());
}

TEST_F(KukaGrasp, AnEndedTerminationConditionStopsPickupAndTransferBeforeTheirInverseKinematics)
{
    // a planner's time limit reaches into the primitives: once it is over they solve nothing
    const ob::PlannerTerminationCondition ended([] { return true; });
    Trajectory trajectory(&space);
    trajectory.reset(start);
    const double ikBefore = pickup->inverseKinematicsTime();
    EXPECT_FALSE(pickup->propagate(start, target, trajectory, ended));
    EXPECT_EQ(trajectory.size(), 1u);
    EXPECT_EQ(pickup->inverseKinematicsTime(), ikBefore);

    ASSERT_TRUE(pickUp(trajectory));  // without the condition it picks up
    Trajectory carried(&space);
    carried.reset(trajectory.back());
    const double ikHeld = transfer->inverseKinematicsTime();
    EXPECT_FALSE(transfer->propagate(trajectory.back(), target, carried, ended));
    EXPECT_EQ(carried.size(), 1u);
    EXPECT_EQ(transfer->inverseKinematicsTime(), ikHeld);

    // nor does the empty-space planner apply any primitive
    EmptySpacePlanner esp(&space, setup.primitives());
    Trajectory planned(&space);
    ompl::RNG rng(1);
    EXPECT_EQ(esp.plan(start, target, planned, rng, ended), Outcome::Failed);
    EXPECT_EQ(planned.size(), 1u);
}

TEST(KukaGraspSeeds, TransferPlacesTheHeldObjectExactlyAtItsTarget)
{
    // a table per target yaw, made alike: the placing IK's random restarts are the same for both
    // (a cylinder's yaw is free, so the IK does not depend on it)
    for (const double yaw : {0.0, 0.3})
    {
        SCOPED_TRACE("target yaw " + std::to_string(yaw));
        KukaTable kuka(SEED);
        const ManipulationStateSpace &space = kuka.space;
        Trajectory picked(&space);
        ASSERT_TRUE(kuka.pickUp(picked));
        const ob::State *lifted = picked.back();
        const ob::State *to = kuka.withObject(kuka.start, CYL1, {ON_TABLE2, yaw});
        EXPECT_TRUE(kuka.transfer->isUseful(lifted, to));
        Trajectory trajectory(&space);
        ASSERT_TRUE(kuka.carry(lifted, to, trajectory));
        ASSERT_GE(trajectory.size(), 2u);
        ASSERT_LE(trajectory.size(), 3u);  // lifted, placed, (retreated)
        EXPECT_EQ(trajectory.label(0), TRANSFER_CYL1);

        // placed exactly at the target, resting on table 2, keeping its grasp
        const ob::State *placed = trajectory.state(1);
        const Eigen::Vector3d at = space.objectPosition(placed, CYL1);
        EXPECT_EQ(at.x(), ON_TABLE2.x());
        EXPECT_EQ(at.y(), ON_TABLE2.y());
        EXPECT_EQ(at.z(), ON_TABLE2.z());
        EXPECT_NEAR(space.objectYaw(placed, CYL1), yaw, 1e-12);
        EXPECT_EQ(space.restingSurface(placed, CYL1), TABLE2);
        EXPECT_TRUE(Grasping::sameGrasp(space, lifted, placed, CYL1));
        const auto explained = kuka.transfer->explain(lifted, placed);
        ASSERT_TRUE(explained.has_value());
        EXPECT_EQ(*explained, TRANSFER_CYL1);
        // the tool point is where the grasp puts it: at the placed object's centre
        EXPECT_LE((space.toolPosition(placed) - (ON_TABLE2 + Eigen::Vector3d(0.0, 0.0, HALF_LENGTH))).norm(),
                  IK_TOL);

        expectWithinJointLimits(space, trajectory);
        expectOthersKeepTheirPoses(space, trajectory, kuka.start, CYL1);
        // with cyl1 placed no object is held: no more transfer
        EXPECT_FALSE(kuka.transfer->isUseful(trajectory.back(), to));

        // every object rests at the start: nothing to transfer, nothing appended
        EXPECT_FALSE(kuka.transfer->isUseful(kuka.start, to));
        Trajectory none(&space);
        EXPECT_FALSE(kuka.carry(kuka.start, to, none));
        EXPECT_EQ(none.size(), 1u);
    }
}

TEST(KukaGraspSeeds, TransferRetreatsAfterPlacing)
{
    // the placing IK restarts from random joints, so its solution and the retreat from it depend
    // on the seed: every placement must be followed by the retreat
    unsigned int placed = 0;
    for (std::uint_fast32_t seed = 1; seed <= 5; ++seed)
    {
        SCOPED_TRACE("seed " + std::to_string(seed));
        KukaTable kuka(seed);
        Trajectory picked(&kuka.space);
        ASSERT_TRUE(kuka.pickUp(picked));
        Trajectory trajectory(&kuka.space);
        if (!kuka.carry(picked.back(), kuka.target, trajectory))
            continue;  // the placing IK may fail (within its budget of restarts)
        ++placed;
        if (trajectory.size() != 3u)
        {
            ADD_FAILURE() << "no retreat after the placement (" << trajectory.size() << " waypoints)";
            continue;
        }
        EXPECT_EQ(trajectory.label(1), TRANSIT);
        const ob::State *place = trajectory.state(1);
        const ob::State *retreat = trajectory.back();
        EXPECT_FALSE(kuka.space.anyObjectMoves(place, retreat));
        EXPECT_TRUE(kuka.space.robotMoves(place, retreat));
        EXPECT_FALSE(kuka.transfer->explain(place, retreat).has_value());
        // back along the approach axis by the approach distance, the orientation kept
        const Eigen::Vector3d axis = approachAxis(kuka.space, place);
        EXPECT_LE(
            (kuka.space.toolPosition(retreat) - (kuka.space.toolPosition(place) - APPROACH * axis)).norm(),
            IK_TOL);
        EXPECT_LE((approachAxis(kuka.space, retreat) - axis).norm(), IK_TOL);
    }
    EXPECT_GE(placed, 3u);
}

TEST(KukaGraspSeeds, TransferWithAPlaceHeightComesStraightDownOntoThePlace)
{
    // the grasping and placing IK restart from random joints: every placement must come from above
    constexpr double PLACE_HEIGHT = 0.05;
    unsigned int placedCount = 0;
    for (std::uint_fast32_t seed = 1; seed <= 5; ++seed)
    {
        SCOPED_TRACE("seed " + std::to_string(seed));
        KukaTable kuka(seed, "0.05");
        const ManipulationStateSpace &space = kuka.space;
        ASSERT_EQ(kuka.transfer->placeHeight(), PLACE_HEIGHT);
        Trajectory picked(&space);
        Trajectory trajectory(&space);
        if (!kuka.pickUp(picked) || !kuka.carry(picked.back(), kuka.target, trajectory))
            continue;  // the IK may fail (within its budget of restarts)
        ++placedCount;
        const ob::State *lifted = picked.back();
        ASSERT_EQ(trajectory.size(), 4u);  // lifted, above the place, placed, retreated
        EXPECT_EQ(trajectory.label(0), TRANSFER_CYL1);
        EXPECT_EQ(trajectory.label(1), TRANSFER_CYL1);
        EXPECT_EQ(trajectory.label(2), TRANSIT);
        const ob::State *above = trajectory.state(1);
        const ob::State *placed = trajectory.state(2);

        // held the same way above the place as when lifted, placed exactly at the target
        EXPECT_TRUE(held(space, above, CYL1));
        EXPECT_TRUE(Grasping::sameGrasp(space, lifted, above, CYL1));
        EXPECT_LE((space.objectPosition(above, CYL1) - (ON_TABLE2 + Eigen::Vector3d(0.0, 0.0, PLACE_HEIGHT)))
                      .norm(),
                  IK_TOL);
        EXPECT_EQ(space.objectPosition(placed, CYL1), ON_TABLE2);
        EXPECT_EQ(space.restingSurface(placed, CYL1), TABLE2);
        EXPECT_TRUE(Grasping::sameGrasp(space, above, placed, CYL1));
        const auto explained = kuka.transfer->explain(above, placed);
        ASSERT_TRUE(explained.has_value());
        EXPECT_EQ(*explained, TRANSFER_CYL1);

        // straight down: the tool keeps its orientation and stays over the place on the way
        EXPECT_LE((toolFrameOf(space, above).linear() - toolFrameOf(space, placed).linear()).norm(), IK_TOL);
        ob::State *between = space.allocState();
        for (const double t : {0.25, 0.5, 0.75})
        {
            space.interpolate(above, placed, t, between);
            const Eigen::Vector3d drift = space.toolPosition(between) - space.toolPosition(placed);
            EXPECT_LT(drift.head<2>().norm(), 0.005) << "at " << t;
            EXPECT_GT(drift.z(), 0.0) << "at " << t;
        }
        space.freeState(between);
        expectWithinJointLimits(space, trajectory);
        expectOthersKeepTheirPoses(space, trajectory, kuka.start, CYL1);
    }
    EXPECT_GE(placedCount, 3u);
}

TEST_F(KukaGrasp, HeldObjectKeepsItsPoseInTheToolAlongTheLiftAndTheTransfer)
{
    Trajectory picked(&space);
    ASSERT_TRUE(pickUp(picked));
    const ob::State *grasp = picked.state(picked.size() - 2);
    const ob::State *lifted = picked.back();
    Trajectory transferred(&space);
    ASSERT_TRUE(carry(lifted, target, transferred));
    const ob::State *placed = transferred.state(1);

    ob::State *s = space.allocState();
    for (const auto &[a, b] : {std::pair{grasp, lifted}, std::pair{lifted, placed}})
    {
        const Eigen::Vector3d reference = inTool(space, a, CYL1);
        for (int step = 1; step <= 9; ++step)
        {
            const double t = 0.1 * step;
            space.interpolate(a, b, t, s);
            EXPECT_LE((inTool(space, s, CYL1) - reference).norm(), 1e-6)
                << "t " << t << ": " << inTool(space, s, CYL1).transpose() << " vs " << reference.transpose();
            // the robot interpolates its joints; the other objects stay where they are
            for (unsigned int j = 0; j < space.robotDimension(); ++j)
            {
                EXPECT_NEAR(space.robotValues(s)[j],
                            (1.0 - t) * space.robotValues(a)[j] + t * space.robotValues(b)[j], 1e-12);
            }
            for (unsigned int i = 0; i < space.objectCount(); ++i)
            {
                if (i != CYL1)
                {
                    EXPECT_EQ(space.objectPosition(s, i), space.objectPosition(a, i));
                }
            }
        }
    }
    space.freeState(s);
}

TEST_F(KukaGrasp, EmptySpacePlannerReachesTheTargetOnTable2)
{
    EmptySpacePlanner esp(&space, setup.primitives());
    unsigned int reached = 0;
    for (std::uint_fast32_t seed = 1; seed <= 5; ++seed)
    {
        SCOPED_TRACE("seed " + std::to_string(seed));
        ompl::RNG rng;
        rng.setLocalSeed(seed);
        Trajectory trajectory(&space);
        if (esp.plan(start, target, trajectory, rng) != Outcome::Reached)
            continue;
        ++reached;
        EXPECT_TRUE(space.equalStates(trajectory.back(), target));
        // cyl1 moves only by a pickup or a transfer of its own; no other object moves
        bool pickedUp = false, transferred = false;
        for (std::size_t k = 0; k + 1 < trajectory.size(); ++k)
        {
            for (unsigned int i = 0; i < space.objectCount(); ++i)
            {
                if (i != CYL1)
                {
                    EXPECT_FALSE(space.objectMoves(trajectory.state(k), trajectory.state(k + 1), i));
                }
            }
            if (space.objectMoves(trajectory.state(k), trajectory.state(k + 1), CYL1))
            {
                EXPECT_TRUE(trajectory.label(k) == PICKUP_CYL1 || trajectory.label(k) == TRANSFER_CYL1)
                    << "segment " << k;
            }
            pickedUp |= trajectory.label(k) == PICKUP_CYL1;
            transferred |= trajectory.label(k) == TRANSFER_CYL1;
        }
        EXPECT_TRUE(pickedUp);
        EXPECT_TRUE(transferred);
    }
    EXPECT_GE(reached, 4u);
}

TEST(KukaGraspSeeds, SameSeedSamePickup)
{
    KukaTable first(7);
    Trajectory a(&first.space);
    ASSERT_TRUE(first.pickUp(a));
    KukaTable second(7);
    Trajectory b(&second.space);
    ASSERT_TRUE(second.pickUp(b));

    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        EXPECT_TRUE(first.space.equalStates(a.state(k), b.state(k))) << "waypoint " << k;
    for (std::size_t k = 0; k + 1 < a.size(); ++k)
        EXPECT_EQ(a.label(k), b.label(k)) << "segment " << k;
}
