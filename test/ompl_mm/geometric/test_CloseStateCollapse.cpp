// Tests for collapseCloseStates: OMPL's collapseCloseVertices step for step, but stopping at its
// termination condition.
#include <gtest/gtest.h>

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ompl_mm/geometric/CloseStateCollapse.h"

using namespace ompl_mm;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** A plane with a disc of radius 1 at the origin in the way. */
    ob::SpaceInformationPtr planeWithDisc()
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(-10.0, 10.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(
            [](const ob::State *state)
            {
                const double *v = state->as<ob::RealVectorStateSpace::StateType>()->values;
                return std::hypot(v[0], v[1]) > 1.0;
            });
        si->setStateValidityCheckingResolution(0.001);
        si->setup();
        return si;
    }

    /** A wandering path around the disc: count random states near a ring of radius 3, in order. */
    og::PathGeometric wanderingPath(const ob::SpaceInformationPtr &si, unsigned int count, unsigned int seed)
    {
        ompl::RNG rng(seed);
        og::PathGeometric path(si);
        ob::State *state = si->allocState();
        for (unsigned int k = 0; k < count; ++k)
        {
            const double angle = 2.0 * M_PI * k / count;
            double *v = state->as<ob::RealVectorStateSpace::StateType>()->values;
            v[0] = 3.0 * std::cos(angle) + rng.uniformReal(-0.8, 0.8);
            v[1] = 3.0 * std::sin(angle) + rng.uniformReal(-0.8, 0.8);
            path.append(state);
        }
        si->freeState(state);
        return path;
    }

    std::vector<std::vector<double>> valuesOf(const og::PathGeometric &path)
    {
        std::vector<std::vector<double>> values;
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
        {
            std::vector<double> state;
            path.getSpaceInformation()->getStateSpace()->copyToReals(state, path.getState(i));
            values.push_back(state);
        }
        return values;
    }
}  // namespace

TEST(CloseStateCollapse, GivesOmplsPathStepForStep)
{
    const ob::SpaceInformationPtr si = planeWithDisc();
    unsigned int collapsed = 0;
    for (unsigned int seed = 1; seed <= 20; ++seed)
    {
        og::PathGeometric ours = wanderingPath(si, 60, seed);
        og::PathGeometric omplsOwn(ours);
        og::PathSimplifier simplifier(si);
        const bool omplChanged = simplifier.collapseCloseVertices(omplsOwn);
        EXPECT_EQ(collapseCloseStates(ours, ob::plannerNonTerminatingCondition()), omplChanged) << seed;
        EXPECT_EQ(valuesOf(ours), valuesOf(omplsOwn)) << seed;
        collapsed += ours.getStateCount() < 60 ? 1 : 0;
    }
    EXPECT_GT(collapsed, 15u) << "the wandering paths give it work";
}

TEST(CloseStateCollapse, MovesOnFromAPairThatFailsAsOmplDoes)
{
    // over the disc and down past it: the closest pair (the first and third states) would cut
    // through the disc, the next closest (the third and fifth) passes it: collapsed after the
    // failure, as OMPL does
    const ob::SpaceInformationPtr si = planeWithDisc();
    og::PathGeometric ours(si);
    ob::State *state = si->allocState();
    for (const auto &[x, y] : std::vector<std::pair<double, double>>{
             {-1.2, 0.05}, {0.0, 1.5}, {1.2, 0.05}, {1.2, -3.0}, {3.0, -3.0}})
    {
        double *v = state->as<ob::RealVectorStateSpace::StateType>()->values;
        v[0] = x;
        v[1] = y;
        ours.append(state);
    }
    si->freeState(state);
    og::PathGeometric omplsOwn(ours);
    og::PathSimplifier simplifier(si);
    ASSERT_TRUE(simplifier.collapseCloseVertices(omplsOwn));
    EXPECT_TRUE(collapseCloseStates(ours, ob::plannerNonTerminatingCondition()));
    EXPECT_EQ(valuesOf(ours), valuesOf(omplsOwn));
    EXPECT_EQ(ours.getStateCount(), 4u);
}

TEST(CloseStateCollapse, StopsAtItsConditionAndKeepsThePathWhole)
{
    const ob::SpaceInformationPtr si = planeWithDisc();
    og::PathGeometric path = wanderingPath(si, 60, 1);
    const std::vector<std::vector<double>> before = valuesOf(path);
    // already true: nothing is done
    EXPECT_FALSE(collapseCloseStates(path, ob::plannerAlwaysTerminatingCondition()));
    EXPECT_EQ(valuesOf(path), before);
    // true after a few motion checks: fewer steps than without a condition, and every state
    // left is one of the path's
    unsigned int polls = 0;
    og::PathGeometric stopped(path), whole(path);
    collapseCloseStates(stopped, ob::PlannerTerminationCondition([&] { return ++polls > 65; }));
    collapseCloseStates(whole, ob::plannerNonTerminatingCondition());
    EXPECT_GT(stopped.getStateCount(), whole.getStateCount());
    for (const std::vector<double> &state : valuesOf(stopped))
        EXPECT_NE(std::find(before.begin(), before.end(), state), before.end());
}

TEST(CloseStateCollapse, PathsOfFewerThanThreeStatesStay)
{
    const ob::SpaceInformationPtr si = planeWithDisc();
    og::PathGeometric path = wanderingPath(si, 2, 1);
    EXPECT_FALSE(collapseCloseStates(path, ob::plannerNonTerminatingCondition()));
    EXPECT_EQ(path.getStateCount(), 2u);
}
