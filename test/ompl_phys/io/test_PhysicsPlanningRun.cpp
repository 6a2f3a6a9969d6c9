// Tests for PhysicsPlanningRun: a run of physics scene 1 solves and re-simulates its controls into
// the goal; the same request gives the same record (times aside); an impossible goal is an input
// error at its line; a stop that holds from the start ends the run unsolved.
#include "ompl_phys/io/PhysicsPlanningRun.h"

#include "common/PlanningRunSupport.h"
#include "ompl_phys/common/PhysicsTestSupport.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

using namespace ompl_phys;
using namespace ompl_phys::test;
using ompl_core::test::NEVER_STOP;
using ompl_core::test::STOP_AT_ONCE;

static PhysicsPlanningRequest seeded(std::uint32_t seed)
{
    return ompl_core::test::seededRequest<PhysicsPlanningRequest>(seed, 60.0);
}

TEST(PhysicsPlanningRun, SolvesScene1AndReSimulatesItsControlsIntoTheGoal)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    PhysicsPlanningRun run(benchmarkScene(1), seeded(2));
    EXPECT_EQ(run.request().planner, "kpiece");
    EXPECT_EQ(run.timeLimit(), 60.0);
    run.solve(NEVER_STOP);
    ASSERT_TRUE(run.solved());
    ASSERT_NE(run.simulated(), nullptr);
    EXPECT_TRUE(run.simulated()->reachesGoal);
    const ompl_core::RunResult record = run.record();
    EXPECT_TRUE(record.solved);
    EXPECT_EQ(record.run.planner, "kpiece");
    ASSERT_NE(record.details.find("reaches_goal"), nullptr);
    EXPECT_EQ(std::get<bool>(record.details.find("reaches_goal")->value), true);
    ASSERT_NE(record.details.find("action"), nullptr);
    EXPECT_EQ(std::get<double>(record.details.find("action")->value), run.simulated()->metrics.action);
    EXPECT_NE(record.details.find("phases_s.solve"), nullptr);
}

TEST(PhysicsPlanningRun, TheSameRequestGivesTheSameRecord)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    PhysicsPlanningRun first(benchmarkScene(1), seeded(4));
    first.solve(NEVER_STOP);
    PhysicsPlanningRun second(benchmarkScene(1), seeded(4));
    second.solve(NEVER_STOP);
    ASSERT_TRUE(first.solved());
    EXPECT_EQ(ompl_core::test::firstDifferenceBesidesTimes(first.record().details, second.record().details),
              "");
}

TEST(PhysicsPlanningRun, AnImpossibleGoalIsAnInputErrorAtItsLine)
{
    std::vector<std::string> lines = smallSceneLines();
    lines.at(6) =
        R"(  <body name="wall" kind="fixed"><origin xyz="0.8 -0.621 0.1"/><box size="1 0.2 0.2"/></body>)";
    const PhysicsScene scene = parsePhysicsScene(joinLines(lines), "test.xml");
    EXPECT_EQ(inputErrorOf([&] { PhysicsPlanningRun run(scene, seeded(1)); }),
              "test.xml:15: the goal cannot be reached: fixed body 'wall' covers its centre");
}

TEST(PhysicsPlanningRun, AStopThatHoldsFromTheStartEndsTheRunUnsolved)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    PhysicsPlanningRun run(benchmarkScene(1), seeded(1));
    run.solve(STOP_AT_ONCE);
    EXPECT_FALSE(run.solved());
    EXPECT_EQ(run.simulated(), nullptr);
    EXPECT_FALSE(run.record().solved);
}
