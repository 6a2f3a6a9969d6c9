// Tests for ToolPathStraightener: on KUKA TABLE a pickup and a transfer from the upright start get
// shorter tool paths that stay valid (PathGeometric::check()), keep their ends and keep the carried
// object in its grasp; a mobile base, whose tool moves straight already, is left as it is.
#include "ompl_mm/geometric/ToolPathStraightener.h"

#include "ompl_mm/primitives/Grasping.h"
#include "ompl_mm/primitives/Pickup.h"
#include "ompl_mm/primitives/TransferRigid.h"
#include "ompl_mm/scene/SceneLoader.h"

#include "common/MobileBlocked.h"
#include "ompl_core/run/GlobalSeed.h"

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr unsigned int CYL3 = 2;

    template <class P>
    std::shared_ptr<P> primitiveOf(const ManipulationSetup &setup)
    {
        for (const PrimitivePtr &primitive : setup.primitives())
            if (auto p = std::dynamic_pointer_cast<P>(primitive))
                return p;
        return nullptr;
    }

    /** Appends the trajectory's waypoints after its first to path. */
    void append(ManipulationPath &path, const Trajectory &trajectory)
    {
        for (std::size_t k = 1; k < trajectory.size(); ++k)
            path.appendLabelled(trajectory.state(k), trajectory.label(k - 1));
    }

    /** KUKA TABLE, OMPL seeded first: its primitives' random generators are made with the setup. */
    Scene seededKukaTable(std::uint32_t seed)
    {
        ompl_core::reseedOmpl(seed);
        return loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml");
    }

    class KukaStraightening : public MobileBlockedTest
    {
    protected:
        KukaStraightening() : MobileBlockedTest(seededKukaTable(1)) {}
    };
}  // namespace

TEST_F(KukaStraightening, APickupAndATransferGetShorterAndStayValid)
{
    const ob::SpaceInformationPtr &si = setup_.getSpaceInformation();
    si->setup();
    const ob::State *start = startCopy();
    // cyl3 (object 2, the one furthest from the others) from table 1 to table 2
    ob::State *target = startCopy();
    space_.setObjectPose(target, CYL3, {Eigen::Vector3d(0.33, -0.5, 0.43), 0.0});
    Trajectory picked(&space_), carried(&space_);
    picked.reset(start);
    ASSERT_TRUE(primitiveOf<Pickup>(setup_)->propagate(start, target, picked));
    carried.reset(picked.back());
    ASSERT_TRUE(primitiveOf<TransferRigid>(setup_)->propagate(picked.back(), target, carried));
    ManipulationPath path(si);
    path.appendFirst(start);
    append(path, picked);
    append(path, carried);
    ASSERT_TRUE(path.check());
    const ManipulationPath before(path);

    ToolPathStraightener straightener(si);
    const unsigned int added = straightener.straighten(path, ob::plannerNonTerminatingCondition());
    EXPECT_GT(added, 0u);
    EXPECT_EQ(path.getStateCount(), before.getStateCount() + added);
    EXPECT_LT(path.toolPathLength(), before.toolPathLength() - 0.05);
    EXPECT_TRUE(path.check());
    EXPECT_TRUE(space_.equalStates(path.getState(0), before.getState(0)));
    EXPECT_TRUE(space_.equalStates(path.getState(path.getStateCount() - 1),
                                   before.getState(before.getStateCount() - 1)));
    EXPECT_GT(straightener.ikTime(), 0.0);
    for (std::size_t k = 0; k + 1 < path.getStateCount(); ++k)
        if (path.label(k).kind == PrimitiveKind::Transfer)
        {
            EXPECT_TRUE(Grasping::sameGrasp(space_, path.getState(k), path.getState(k + 1), CYL3))
                << "segment " << k;
        }
}

TEST_F(MobileBlockedTest, AMobileBasesToolMovesStraightAlready)
{
    const ob::SpaceInformationPtr &si = setup_.getSpaceInformation();
    si->setup();
    ob::State *far = startCopy();
    space_.robotValues(far)[0] = -2.0;
    ManipulationPath path(si);
    path.appendFirst(startCopy());
    path.appendLabelled(far, {PrimitiveKind::Transit, -1});
    ToolPathStraightener straightener(si);
    EXPECT_EQ(straightener.straighten(path, ob::plannerNonTerminatingCondition()), 0u);
    EXPECT_EQ(path.getStateCount(), 2u);
}

TEST(ToolPathStraightenerInput, NeedsTheManipulationMotionValidator)
{
    const ManipulationSetup setup(mobileBlockedScene());
    auto si = std::make_shared<ob::SpaceInformation>(setup.getStateSpace());
    si->setStateValidityChecker(setup.getStateValidityChecker());
    si->setup();
    EXPECT_THROW(ToolPathStraightener{si}, ompl::Exception);
}
