// Tests for OmplVersions: the infeasible status is OMPL's own where it exists, and the shortcutting
// adapters run OMPL's algorithms (a detour around nothing becomes a straight line, every state valid).
#include "ompl_core/compat/OmplVersions.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>

using namespace ompl_core;

namespace
{
    /** A unit square with nothing in it. */
    ompl::base::SpaceInformationPtr emptySquare()
    {
        auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        auto si = std::make_shared<ompl::base::SpaceInformation>(space);
        si->setStateValidityChecker([](const ompl::base::State *) { return true; });
        si->setup();
        return si;
    }

    /** A path from (0.1, 0.1) to (0.9, 0.1) through (0.5, 0.9): twice as long as the straight line. */
    ompl::geometric::PathGeometric detour(const ompl::base::SpaceInformationPtr &si)
    {
        ompl::geometric::PathGeometric path(si);
        for (const auto &[x, y] : {std::pair{0.1, 0.1}, {0.3, 0.5}, {0.5, 0.9}, {0.7, 0.5}, {0.9, 0.1}})
        {
            ompl::base::State *state = si->allocState();
            auto *values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
            values[0] = x;
            values[1] = y;
            path.append(state);
            si->freeState(state);
        }
        return path;
    }
}  // namespace

TEST(OmplVersions, TheInfeasibleStatusIsOMPLsOwnWhereItExists)
{
    // OMPL 1.6 added INFEASIBLE after ABORT, the last status of OMPL 1.5 (its asString() has no name
    // for either, up to 2.0.2 at least)
    using Status = ompl::base::PlannerStatus;
    const int expected = OMPL_VERSION_VALUE >= 1006000 ? Status::ABORT + 1 : Status::INVALID_GOAL;
    EXPECT_EQ(static_cast<int>(infeasibleStatus()), expected);
    EXPECT_FALSE(Status(infeasibleStatus()));
}

TEST(OmplVersions, PartialShortcutStraightensADetour)
{
    ompl::RNG::setSeed(7);
    const ompl::base::SpaceInformationPtr si = emptySquare();
    ompl::geometric::PathGeometric path = detour(si);
    const double before = path.length();
    ompl::geometric::PathSimplifier simplifier(si);
    bool changed = false;
    for (int pass = 0; pass < 20; ++pass)
        changed = partialShortcut(simplifier, path) || changed;
    EXPECT_TRUE(changed);
    EXPECT_LT(path.length(), 0.9 * before);
    EXPECT_TRUE(path.check());
}

TEST(OmplVersions, RopeShortcutStraightensADetourWhereOMPLHasIt)
{
    const ompl::base::SpaceInformationPtr si = emptySquare();
    ompl::geometric::PathGeometric path = detour(si);
    const double before = path.length();
    ompl::geometric::PathSimplifier simplifier(si);
    const bool changed = ropeShortcut(simplifier, path);
    EXPECT_TRUE(path.check());
    if (OMPL_VERSION_VALUE >= 1007000)
    {
        EXPECT_TRUE(changed);
        EXPECT_NEAR(path.length(), 0.8, 1e-6) << "the straight line from (0.1, 0.1) to (0.9, 0.1)";
    }
    else
    {
        EXPECT_FALSE(changed);
        EXPECT_EQ(path.length(), before);
    }
}
