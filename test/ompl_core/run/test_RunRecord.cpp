// Tests for RunRecord: keys are checked, entries keep their order and are found by dotted paths, and
// writeRunJson writes the exact JSON text (null for non-finite numbers, nested records indented).
#include "ompl_core/run/RunRecord.h"

#include "common/InputErrors.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>

using namespace ompl_core;
using ompl_core::test::exceptionOf;

namespace
{

    std::string json(const RunResult &result)
    {
        std::ostringstream out;
        writeRunJson(out, result);
        return out.str();
    }
}  // namespace

TEST(RunRecord, RejectsEmptyAndDottedKeys)
{
    RunRecord record;
    EXPECT_EQ(exceptionOf([&] { record.addNumber("", 1.0); }),
              "RunRecord: bad key '': keys are non-empty and hold no '.'");
    EXPECT_EQ(exceptionOf([&] { record.addCount("stats.time", 1); }),
              "RunRecord: bad key 'stats.time': keys are non-empty and hold no '.'");
    EXPECT_EQ(exceptionOf([&] { record.addText(".", "x"); }),
              "RunRecord: bad key '.': keys are non-empty and hold no '.'");
    EXPECT_TRUE(record.empty());
    // any other text is a key
    EXPECT_EQ(exceptionOf([&] { record.addFlag(" odd key_1 ", true); }), "");
    EXPECT_FALSE(record.empty());
}

TEST(RunRecord, RejectsAKeyUsedBeforeWhateverItsType)
{
    RunRecord record;
    record.addNumber("time", 1.0);
    const std::string used = "RunRecord: key 'time' is already used";
    EXPECT_EQ(exceptionOf([&] { record.addNumber("time", 2.0); }), used);
    EXPECT_EQ(exceptionOf([&] { record.addCount("time", 2); }), used);
    EXPECT_EQ(exceptionOf([&] { record.addFlag("time", false); }), used);
    EXPECT_EQ(exceptionOf([&] { record.addText("time", "2"); }), used);
    EXPECT_EQ(exceptionOf([&] { record.addTexts("time", {"2"}); }), used);
    EXPECT_EQ(exceptionOf([&] { record.addRecord("time", RunRecord()); }), used);
    // the rejected values were not added
    ASSERT_EQ(record.entries().size(), 1u);
    EXPECT_EQ(std::get<double>(record.entries().front().value), 1.0);
    // keys are case-sensitive, and a nested record has its own keys
    EXPECT_EQ(exceptionOf([&] { record.addNumber("Time", 2.0); }), "");
    RunRecord nested;
    nested.addNumber("time", 3.0);
    EXPECT_EQ(exceptionOf([&] { record.addRecord("stats", nested); }), "");
}

TEST(RunRecord, FindsEntriesByDottedPath)
{
    RunRecord inner;
    inner.addCount("iterations", 12);
    RunRecord stats;
    stats.addRecord("inner", inner).addNumber("time", 0.5);
    RunRecord record;
    record.addText("name", "x").addRecord("stats", stats);

    const RunRecord::Entry *iterations = record.find("stats.inner.iterations");
    ASSERT_NE(iterations, nullptr);
    EXPECT_EQ(std::get<std::uint64_t>(iterations->value), 12u);
    ASSERT_NE(record.find("stats.time"), nullptr);
    EXPECT_EQ(std::get<double>(record.find("stats.time")->value), 0.5);
    EXPECT_EQ(record.find("stats.missing"), nullptr);
    EXPECT_EQ(record.find("name.length"), nullptr);  // name is not a record
    EXPECT_EQ(record.find("missing"), nullptr);
    EXPECT_EQ(record.find(""), nullptr);
    // addRecord copies: changing the original afterwards changes nothing
    stats.addNumber("later", 1.0);
    EXPECT_EQ(record.find("stats.later"), nullptr);
}

TEST(WriteRunJson, ExactTextWithNullsAndNestedRecords)
{
    RunResult result;
    result.run = {"scene \"1\"", "rrt", 7, 1.5};
    result.solved = true;
    result.approximate = false;
    result.status = "Exact solution";
    result.time = std::numeric_limits<double>::quiet_NaN();

    RunRecord deepest;
    deepest.addNumber("x", -std::numeric_limits<double>::infinity());
    RunRecord stats;
    stats.addNumber("time", std::numeric_limits<double>::infinity())
        .addCount("vertices", 18446744073709551615u)
        .addRecord("inner", deepest)
        .addRecord("empty", RunRecord());
    result.details.addNumber("length", 0.12345678912345)
        .addNumber("tiny", 1e-20)
        .addFlag("ok", false)
        .addText("note", "a\\b\n")
        .addTexts("names", {"a", "b\"c"})
        .addTexts("none", {})
        .addRecord("stats", stats)
        .addNumber("after", -2.0);

    const std::string expected =
        "{\n"
        "  \"scene\": \"scene \\\"1\\\"\",\n"
        "  \"planner\": \"rrt\",\n"
        "  \"seed\": 7,\n"
        "  \"time_limit_s\": 1.5,\n"
        "  \"solved\": true,\n"
        "  \"approximate\": false,\n"
        "  \"status\": \"Exact solution\",\n"
        "  \"time_s\": null,\n"
        "  \"length\": 0.1234567891,\n"
        "  \"tiny\": 1e-20,\n"
        "  \"ok\": false,\n"
        "  \"note\": \"a\\\\b\\u000a\",\n"
        "  \"names\": [\"a\", \"b\\\"c\"],\n"
        "  \"none\": [],\n"
        "  \"stats\": {\n"
        "    \"time\": null,\n"
        "    \"vertices\": 18446744073709551615,\n"
        "    \"inner\": {\n"
        "      \"x\": null\n"
        "    },\n"
        "    \"empty\": {\n"
        "    }\n"
        "  },\n"
        "  \"after\": -2\n"
        "}\n";
    EXPECT_EQ(json(result), expected);
}

TEST(WriteRunJson, WithoutDetailsOnlyTheHeader)
{
    RunResult result;
    result.run = {"s", "p", 4294967295u, 60.0};
    result.status = "Timeout";
    result.time = 60.000000001;
    EXPECT_EQ(json(result),
              "{\n"
              "  \"scene\": \"s\",\n"
              "  \"planner\": \"p\",\n"
              "  \"seed\": 4294967295,\n"
              "  \"time_limit_s\": 60,\n"
              "  \"solved\": false,\n"
              "  \"approximate\": false,\n"
              "  \"status\": \"Timeout\",\n"
              "  \"time_s\": 60\n"
              "}\n");
}

TEST(RunResult, TakesSolvedApproximateAndStatusFromTheProblem)
{
    auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
    space->setBounds(0.0, 1.0);
    auto si = std::make_shared<ompl::base::SpaceInformation>(space);
    si->setup();
    const ompl::base::ProblemDefinition pdef(si);
    const RunDescription run{"s", "p", 3, 2.0};
    const RunResult result = runResult(run, pdef, ompl::base::PlannerStatus::TIMEOUT, 1.25);
    EXPECT_EQ(result.run.scene, "s");
    EXPECT_EQ(result.run.seed, 3u);
    EXPECT_FALSE(result.solved);
    EXPECT_FALSE(result.approximate);
    EXPECT_EQ(result.status, "Timeout");
    EXPECT_EQ(result.time, 1.25);
    EXPECT_TRUE(result.details.empty());
}

TEST(RunResult, AnApproximateSolutionIsNotSolved)
{
    auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
    space->setBounds(0.0, 1.0);
    auto si = std::make_shared<ompl::base::SpaceInformation>(space);
    si->setup();
    ompl::base::ProblemDefinition pdef(si);
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si);
    pdef.addSolutionPath(path, true, 0.3, "p");
    const RunResult approximate =
        runResult({"s", "p", 1, 2.0}, pdef, ompl::base::PlannerStatus::APPROXIMATE_SOLUTION, 2.0);
    EXPECT_FALSE(approximate.solved);
    EXPECT_TRUE(approximate.approximate);
    EXPECT_EQ(approximate.status, "Approximate solution");

    pdef.clearSolutionPaths();
    pdef.addSolutionPath(path, false, 0.0, "p");
    const RunResult exact =
        runResult({"s", "p", 1, 2.0}, pdef, ompl::base::PlannerStatus::EXACT_SOLUTION, 0.5);
    EXPECT_TRUE(exact.solved);
    EXPECT_FALSE(exact.approximate);
}
