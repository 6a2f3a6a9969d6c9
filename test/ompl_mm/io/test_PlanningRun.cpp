// Tests for PlanningRun: a run of MOBILE BLOCKED solves and re-checks its path; the same request
// gives the same record (times aside); the scene's planner is the default; an impossible goal is an
// input error at its line; a stop that holds from the start ends the run unsolved; a race of searches
// (threads) repeats per seed and thread count, and its bad requests are input errors.
#include "ompl_mm/io/PlanningRun.h"

#include "common/MobileBlocked.h"
#include "common/PlanningRunSupport.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;

using ompl_core::test::NEVER_STOP;
using ompl_core::test::STOP_AT_ONCE;

static PlanningRequest seeded(std::uint32_t seed)
{
    return ompl_core::test::seededRequest<PlanningRequest>(seed);
}

TEST(PlanningRun, SolvesMobileBlockedWithTheScenesPlannerAndRechecksThePath)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    PlanningRun run(mobileBlockedScene(), seeded(3), 0.25);
    EXPECT_EQ(run.request().planner, "mopl");
    EXPECT_EQ(run.timeLimit(), mobileBlockedScene().timeLimit);
    run.solve(NEVER_STOP);
    ASSERT_TRUE(run.solved());
    ASSERT_TRUE(run.pathValid().has_value());
    EXPECT_TRUE(*run.pathValid());
    const ompl_core::RunResult record = run.record();
    EXPECT_TRUE(record.solved);
    EXPECT_EQ(record.run.seed, 3u);
    EXPECT_EQ(record.run.planner, "mopl");
    ASSERT_NE(record.details.find("phases_s.load"), nullptr);
    EXPECT_EQ(std::get<double>(record.details.find("phases_s.load")->value), 0.25);
    ASSERT_NE(record.details.find("path_valid"), nullptr);
    EXPECT_EQ(std::get<bool>(record.details.find("path_valid")->value), true);
}

TEST(PlanningRun, TheSameRequestGivesTheSameRecord)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    PlanningRun first(mobileBlockedScene(), seeded(5));
    first.solve(NEVER_STOP);
    PlanningRun second(mobileBlockedScene(), seeded(5));
    second.solve(NEVER_STOP);
    ASSERT_TRUE(first.solved());
    EXPECT_EQ(ompl_core::test::firstDifferenceBesidesTimes(first.record().details, second.record().details),
              "");
    EXPECT_EQ(first.setup().manipulationPath().getStateCount(),
              second.setup().manipulationPath().getStateCount());
}

TEST(PlanningRun, AnImpossibleGoalIsAnInputErrorAtItsLine)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    Scene scene = mobileBlockedScene();
    scene.objectGoals.at(0).position = {-1.0, 0.0, std::nullopt};  // inside block1
    EXPECT_TRUE(startsWith(inputErrorOf([&] { PlanningRun run(scene, seeded(1)); }),
                           scene.objectGoals[0].where.str() + ": the goal cannot be reached"));
}

TEST(PlanningRun, AnUnknownPlannerIsAnInputError)
{
    PlanningRequest request = seeded(1);
    request.planner = "no_such_planner";
    EXPECT_TRUE(contains(inputErrorOf([&] { PlanningRun run(mobileBlockedScene(), request); }),
                         "unknown planner 'no_such_planner'"));
}

TEST(PlanningRun, AStopThatHoldsFromTheStartEndsTheRunUnsolved)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    PlanningRun run(mobileBlockedScene(), seeded(1));
    run.solve(STOP_AT_ONCE);
    EXPECT_FALSE(run.solved());
    EXPECT_FALSE(run.pathValid().has_value());
    EXPECT_FALSE(run.record().solved);
}

TEST(PlanningRun, ARaceOfSearchesGivesTheSameRecordForTheSameSeedAndThreads)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    PlanningRequest request = seeded(87);
    request.threads = 2;
    PlanningRun first(mobileBlockedScene(), request);
    first.solve(NEVER_STOP);
    PlanningRun second(mobileBlockedScene(), request);
    second.solve(NEVER_STOP);
    ASSERT_TRUE(first.solved());
    ASSERT_TRUE(first.pathValid().has_value());
    EXPECT_TRUE(*first.pathValid());
    EXPECT_EQ(ompl_core::test::firstDifferenceBesidesTimes(first.record().details, second.record().details),
              "");
    EXPECT_EQ(first.record().time, first.planningTime());
}

TEST(PlanningRun, ThreadsOutOfRangeOrForAnotherPlannerAreInputErrors)
{
    PlanningRequest request = seeded(1);
    request.threads = 0;
    EXPECT_TRUE(contains(inputErrorOf([&] { PlanningRun run(mobileBlockedScene(), request); }),
                         "threads must be 1 to 64, got 0"));
    request.threads = 65;
    EXPECT_TRUE(contains(inputErrorOf([&] { PlanningRun run(mobileBlockedScene(), request); }),
                         "threads must be 1 to 64, got 65"));
    request.threads = 2;
    request.planner = "rrtconnect";
    EXPECT_TRUE(contains(inputErrorOf([&] { PlanningRun run(mobileBlockedScene(), request); }),
                         "threads above 1 race MOPL searches; planner 'rrtconnect'"));
}
