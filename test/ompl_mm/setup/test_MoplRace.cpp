// Tests for MoplRace: the winner is the search that solves in the fewest iterations, as the same
// searches run one after the other show; a race repeats; search 0 keeps the seed; bad races throw.
#include "ompl_mm/setup/MoplRace.h"

#include "common/MobileBlocked.h"
#include "ompl_core/run/GlobalSeed.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** `count` setups of MOBILE BLOCKED, built one after the other after seeding OMPL with 1,
        their searches seeded MoplRace::seedOf(seed, index). */
    std::vector<std::unique_ptr<ManipulationSetup>> seededSetups(unsigned int count, std::uint32_t seed)
    {
        ompl_core::reseedOmpl(1);
        std::vector<std::unique_ptr<ManipulationSetup>> setups;
        for (unsigned int index = 0; index < count; ++index)
        {
            setups.push_back(std::make_unique<ManipulationSetup>(mobileBlockedScene()));
            setups.back()->mopl()->setSeed(MoplRace::seedOf(seed, index));
        }
        return setups;
    }

    std::vector<ManipulationSetup *> pointers(const std::vector<std::unique_ptr<ManipulationSetup>> &setups)
    {
        std::vector<ManipulationSetup *> result;
        for (const auto &setup : setups)
            result.push_back(setup.get());
        return result;
    }
}  // namespace

TEST(MoplRace, TheWinnerIsTheSearchThatSolvesInTheFewestIterations)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (const std::uint32_t seed : {87u, 3u})
    {
        // the same searches one after the other, to the end
        const auto alone = seededSetups(3, seed);
        for (ManipulationSetup *setup : pointers(alone))
            setup->setup();
        std::vector<std::uint64_t> iterations;
        for (ManipulationSetup *setup : pointers(alone))
        {
            ASSERT_EQ(setup->solve(ompl::base::plannerNonTerminatingCondition()),
                      ompl::base::PlannerStatus::EXACT_SOLUTION);
            iterations.push_back(setup->mopl()->statistics().iterations);
        }
        int fewest = 0;
        for (int k = 1; k < 3; ++k)
            if (iterations[k] < iterations[fewest])
                fewest = k;

        const auto racing = seededSetups(3, seed);
        const int winner = MoplRace::solve(pointers(racing), ompl::base::plannerNonTerminatingCondition());
        ASSERT_EQ(winner, fewest) << "seed " << seed;
        const ManipulationSetup &won = *racing[winner];
        EXPECT_EQ(won.mopl()->statistics().iterations, iterations[fewest]);
        EXPECT_EQ(won.manipulationPath().getStateCount(), alone[fewest]->manipulationPath().getStateCount());
        EXPECT_TRUE(won.manipulationPath().check());
        // the others solved later in their own count (before the winner was known), or were
        // stopped before they solved
        for (int k = 0; k < 3; ++k)
        {
            if (k == winner)
                continue;
            const std::uint64_t ran = racing[k]->mopl()->statistics().iterations;
            if (racing[k]->getProblemDefinition()->hasExactSolution())
                EXPECT_EQ(ran, iterations[k]);
            else
                EXPECT_LE(ran, iterations[k]);
        }
    }
}

TEST(MoplRace, SearchZeroKeepsTheSeedAndTheOthersDiffer)
{
    EXPECT_EQ(MoplRace::seedOf(87, 0), 87u);
    EXPECT_NE(MoplRace::seedOf(87, 1), 87u);
    EXPECT_NE(MoplRace::seedOf(87, 1), MoplRace::seedOf(87, 2));
    EXPECT_NE(MoplRace::seedOf(87, 1), 0u);
}

TEST(MoplRace, ARaceOfNoneOrOfAnotherPlannerThrows)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    EXPECT_THROW(MoplRace::solve({}, ompl::base::plannerNonTerminatingCondition()), ompl::Exception);
    ManipulationSetup setup(mobileBlockedScene());
    setup.setPlannerByName("rrtconnect");
    EXPECT_THROW(MoplRace::solve({&setup}, ompl::base::plannerNonTerminatingCondition()), ompl::Exception);
}
