// MOPL and the simplifier with physics-aware pushes (model="physics" on MOBILE BLOCKED's push).
#include "common/MobileBlocked.h"
#include "ompl_mmphys/primitives/PhysicsPrimitives.h"
#include "ompl_mmphys/simulation/PhysicsCheck.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** MOBILE BLOCKED with physics-aware pushes. */
    Scene physicsPushScene()
    {
        Scene scene = mobileBlockedScene();
        scene.setPushModel("physics");
        return scene;
    }

    /** The push segments of path: the values of each one's two ends. */
    std::vector<std::vector<double>> pushSegments(const ManipulationPath &path)
    {
        const auto &space = *path.getSpaceInformation()->getStateSpace();
        std::vector<std::vector<double>> segments;
        for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
            if (path.label(i).kind == PrimitiveKind::Push)
            {
                std::vector<double> from, to;
                space.copyToReals(from, path.getState(i));
                space.copyToReals(to, path.getState(i + 1));
                from.insert(from.end(), to.begin(), to.end());
                segments.push_back(std::move(from));
            }
        return segments;
    }

    class PhysicsAwarePlanningTest : public ::testing::Test
    {
    protected:
        ManipulationSetup setup_{physicsPushScene(), ompl_mmphys::physicsPrimitiveFactory()};
        const ManipulationStateSpace &space_ = *setup_.manipulationSpace();
    };
}  // namespace

TEST_F(PhysicsAwarePlanningTest, OnceTheObjectsMeetTheGoalTheRobotsTransitThereIsPlanned)
{
    // the goal tree cannot root where physics leaves the objects: without the transit planned from
    // the start tree, seed 2 takes tens of thousands of iterations (not solved in 10 s)
    setup_.mopl()->setSeed(2);
    ASSERT_TRUE(setup_.solve(120.0));  // under the sanitizers too
    EXPECT_TRUE(setup_.haveExactSolutionPath());
    EXPECT_LT(setup_.mopl()->statistics().iterations, 5000u);
    const ompl_mmphys::PhysicsCheck check = ompl_mmphys::checkPlan(setup_, setup_.manipulationPath());
    EXPECT_TRUE(check.confirmed) << "largest error " << check.maxPositionError << " m";
}

TEST_F(PhysicsAwarePlanningTest, TheSimplifierSeesThatPushesAreSimulated)
{
    EXPECT_TRUE(ManipulationSimplifier(setup_.getSpaceInformation()).pushesSimulated());
    ManipulationSetup kinematic(mobileBlockedScene(), ompl_mmphys::physicsPrimitiveFactory());
    EXPECT_FALSE(ManipulationSimplifier(kinematic.getSpaceInformation()).pushesSimulated());
}

TEST_F(PhysicsAwarePlanningTest, SmoothingShortensTheStretchesBetweenPushesAndKeepsEveryPush)
{
    setup_.mopl()->setSeed(1);
    ASSERT_TRUE(setup_.solve(120.0));
    ManipulationPath &path = setup_.manipulationPath();
    // a detour into a transit of the path: out sideways to a free place and back
    const auto si = setup_.getSpaceInformation();
    ompl::base::State *aside = space_.allocState();
    std::size_t transit = 0;
    const auto detourFits = [&](std::size_t i)
    {
        if (path.label(i).kind != PrimitiveKind::Transit)
            return false;
        for (int direction = 0; direction < 8; ++direction)
        {
            space_.copyState(aside, path.getState(i));
            space_.robotValues(aside)[0] += 0.4 * std::cos(direction * M_PI / 4.0);
            space_.robotValues(aside)[1] += 0.4 * std::sin(direction * M_PI / 4.0);
            if (si->isValid(aside) && si->checkMotion(path.getState(i), aside) &&
                si->checkMotion(aside, path.getState(i + 1)))
                return true;
        }
        return false;
    };
    while (transit + 1 < path.getStateCount() && !detourFits(transit))
        ++transit;
    ASSERT_LT(transit + 1, path.getStateCount()) << "no transit with a free place beside it";
    ManipulationPath withDetour(si);
    withDetour.appendFirst(path.getState(0));
    for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
    {
        if (i == transit)
            withDetour.appendLabelled(aside, TRANSIT);
        withDetour.appendLabelled(path.getState(i + 1), path.label(i));
    }
    space_.freeState(aside);
    const std::vector<std::vector<double>> pushes = pushSegments(withDetour);
    const double before = withDetour.toolPathLength();
    path = withDetour;

    setup_.smoothSolution(30, 1);
    EXPECT_LT(path.toolPathLength(), before - 0.5) << "the detour (0.8 m of travel) is gone";
    EXPECT_EQ(pushSegments(path), pushes) << "every push is kept as physics made it";
    EXPECT_TRUE(path.check());
    EXPECT_TRUE(ompl_mmphys::checkPlan(setup_, path).confirmed);
}
