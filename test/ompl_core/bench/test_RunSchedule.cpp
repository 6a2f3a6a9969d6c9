// Tests for RunSchedule: --shard K/N is read strictly; a run's seed is FNV-1a of its config seed, problem,
// planner label and repetition (checked against an independent computation), never 0, and changes with
// each of them; runs are ordered problem, planner, repetition, and the shards of one count split them
// exactly, with the seeds of the whole schedule.
#include "ompl_core/bench/RunSchedule.h"

#include "common/InputErrors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace ompl_core;
using ompl_core::test::inputErrorOf;

namespace
{
    /** FNV-1a (64 bits) over the bytes of the seed and index (least significant first), the problem
        and the label (each followed by a zero byte), folded to 32 bits: written out here apart from
        the library's hash. */
    std::uint32_t independentSeed(std::uint32_t configSeed, const std::string &problem,
                                  const std::string &label, std::uint32_t index)
    {
        std::string bytes;
        for (int i = 0; i < 4; ++i)
            bytes += static_cast<char>((configSeed >> (8 * i)) & 0xffu);
        bytes += problem;
        bytes += '\0';
        bytes += label;
        bytes += '\0';
        for (int i = 0; i < 4; ++i)
            bytes += static_cast<char>((index >> (8 * i)) & 0xffu);
        std::uint64_t hash = 0xcbf29ce484222325ull;
        for (const char c : bytes)
            hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
        return static_cast<std::uint32_t>(hash ^ (hash >> 32));
    }

    /** A config of two problems, three planners (two of one type) and runCount runs each. */
    BenchmarkConfig configOf(unsigned int runCount)
    {
        BenchmarkConfig config;
        config.seed = 7;
        config.runCount = runCount;
        config.problems.resize(2);
        config.problems[0].name = "corridor";
        config.problems[1].name = "open";
        config.planners.push_back({"rrt", "rrt", {}, {}});
        config.planners.push_back({"rrt", "rrt_fast", {}, {}});
        config.planners.push_back({"prm", "prm", {}, {}});
        return config;
    }

    /** A run as (problem, planner, index, seed), to compare runs whole. */
    using RunTuple = std::tuple<std::size_t, std::size_t, unsigned int, std::uint32_t>;

    std::vector<RunTuple> tuplesOf(const std::vector<ScheduledRun> &runs)
    {
        std::vector<RunTuple> tuples;
        for (const ScheduledRun &run : runs)
            tuples.emplace_back(run.problem, run.planner, run.index, run.seed);
        return tuples;
    }

    std::string shardError(const std::string &text)
    {
        return inputErrorOf([&] { parseShard(text); });
    }
}  // namespace

TEST(ParseShard, AcceptsKOfN)
{
    const Shard one = parseShard("1/1");
    EXPECT_EQ(one.index, 1u);
    EXPECT_EQ(one.count, 1u);
    const Shard last = parseShard("3/3");
    EXPECT_EQ(last.index, 3u);
    EXPECT_EQ(last.count, 3u);
    const Shard most = parseShard("100000/100000");
    EXPECT_EQ(most.index, 100000u);
    EXPECT_EQ(most.count, MAX_SHARDS);
}

TEST(ParseShard, RejectsKOrNOutOfRange)
{
    EXPECT_EQ(shardError("0/3"), "command line option --shard: '0/3' needs 1 <= K <= N <= 100000");
    EXPECT_EQ(shardError("4/3"), "command line option --shard: '4/3' needs 1 <= K <= N <= 100000");
    EXPECT_EQ(shardError("1/0"), "command line option --shard: '1/0' needs 1 <= K <= N <= 100000");
    EXPECT_EQ(shardError("-1/3"), "command line option --shard: '-1/3' needs 1 <= K <= N <= 100000");
    EXPECT_EQ(shardError("1/100001"), "command line option --shard: '1/100001' needs 1 <= K <= N <= 100000");
}

TEST(ParseShard, RejectsWhatIsNotKSlashN)
{
    EXPECT_EQ(shardError("a/b"), "command line option --shard: expected K/N with whole numbers, got 'a/b'");
    EXPECT_EQ(shardError("1.5/3"),
              "command line option --shard: expected K/N with whole numbers, got '1.5/3'");
    EXPECT_EQ(shardError("1/2.5"),
              "command line option --shard: expected K/N with whole numbers, got '1/2.5'");
    EXPECT_EQ(shardError("3"), "command line option --shard: expected K/N with whole numbers, got '3'");
    EXPECT_EQ(shardError(""), "command line option --shard: expected K/N with whole numbers, got ''");
    EXPECT_EQ(shardError("1/"), "command line option --shard: expected K/N with whole numbers, got '1/'");
    EXPECT_EQ(shardError("1/2/3"),
              "command line option --shard: expected K/N with whole numbers, got '1/2/3'");
    EXPECT_EQ(shardError(" 1/3"), "command line option --shard: expected K/N with whole numbers, got ' 1/3'");
}

TEST(RunSeed, IsFnv1aOfItsInputs)
{
    EXPECT_EQ(runSeed(1, "p", "rrt", 0), independentSeed(1, "p", "rrt", 0));
    EXPECT_EQ(runSeed(7, "corridor", "rrt_fast", 99), independentSeed(7, "corridor", "rrt_fast", 99));
    EXPECT_EQ(runSeed(4294967295u, "", "", 4294967295u), independentSeed(4294967295u, "", "", 4294967295u));
    // deterministic: the same inputs give the same seed
    EXPECT_EQ(runSeed(3, "open", "prm", 5), runSeed(3, "open", "prm", 5));
}

TEST(RunSeed, IsNeverZero)
{
    // found by search: the folded hash of these inputs is 0, which OMPL would take as "no seed"
    ASSERT_EQ(independentSeed(1, "p", "est", 3413288485u), 0u);
    EXPECT_EQ(runSeed(1, "p", "est", 3413288485u), 1u);
    // and all other seeds are the hash itself
    EXPECT_EQ(runSeed(1, "p", "est", 3413288484u), independentSeed(1, "p", "est", 3413288484u));
    EXPECT_NE(runSeed(1, "p", "est", 3413288484u), 0u);
}

TEST(RunSeed, DiffersWhenAnyInputDiffers)
{
    const std::uint32_t seed = runSeed(1, "corridor", "rrt", 0);
    EXPECT_NE(runSeed(2, "corridor", "rrt", 0), seed);
    EXPECT_NE(runSeed(1, "corridor2", "rrt", 0), seed);
    EXPECT_NE(runSeed(1, "corridor", "rrt2", 0), seed);
    EXPECT_NE(runSeed(1, "corridor", "rrt", 1), seed);
    // the problem and label are kept apart: "ab" + "c" is not "a" + "bc"
    EXPECT_NE(runSeed(1, "ab", "c", 0), runSeed(1, "a", "bc", 0));
    EXPECT_NE(runSeed(1, "abc", "", 0), runSeed(1, "", "abc", 0));
    // the seed and index bytes are kept apart from each other
    EXPECT_NE(runSeed(1, "p", "rrt", 2), runSeed(2, "p", "rrt", 1));
}

TEST(RunSeed, AllSeedsOfAScheduleAreDistinctAndNonZero)
{
    const std::vector<ScheduledRun> runs = scheduleRuns(configOf(1000));
    std::set<std::uint32_t> seeds;
    for (const ScheduledRun &run : runs)
    {
        EXPECT_NE(run.seed, 0u);
        seeds.insert(run.seed);
    }
    // 6000 seeds of 32 bits: a collision has a chance of about 0.4%, and these inputs have none
    EXPECT_EQ(seeds.size(), runs.size());
}

TEST(ScheduleRuns, OrderedByProblemThenPlannerThenRepetition)
{
    const BenchmarkConfig config = configOf(2);
    const std::vector<ScheduledRun> runs = scheduleRuns(config);
    ASSERT_EQ(runs.size(), 12u);
    std::vector<RunTuple> expected;
    for (std::size_t p = 0; p < 2; ++p)
        for (std::size_t q = 0; q < 3; ++q)
            for (unsigned int k = 0; k < 2; ++k)
                expected.emplace_back(
                    p, q, k, independentSeed(7, config.problems[p].name, config.planners[q].label, k));
    EXPECT_EQ(tuplesOf(runs), expected);
    // two planners of one type have the seeds of their labels
    EXPECT_EQ(runs[2].planner, 1u);
    EXPECT_EQ(runs[2].seed, runSeed(7, "corridor", "rrt_fast", 0));
    EXPECT_NE(runs[2].seed, runs[0].seed);
}

TEST(ScheduleRuns, ShardTakesEveryNthRunFromTheKth)
{
    const BenchmarkConfig config = configOf(2);
    const std::vector<RunTuple> all = tuplesOf(scheduleRuns(config));
    const std::vector<RunTuple> second = tuplesOf(scheduleRuns(config, {2, 5}));
    EXPECT_EQ(second, (std::vector<RunTuple>{all[1], all[6], all[11]}));
}

TEST(ScheduleRuns, ShardsHoldEachRunExactlyOnce)
{
    // 2 problems x 3 planners x 5 runs = 30 runs, and 2 x 3 x 4 = 24: 3 shards of 10 and of 8
    for (const unsigned int runCount : {5u, 4u})
    {
        const BenchmarkConfig config = configOf(runCount);
        const std::vector<RunTuple> all = tuplesOf(scheduleRuns(config));
        ASSERT_EQ(all.size(), 6u * runCount);
        std::vector<RunTuple> joined;
        for (unsigned int k = 1; k <= 3; ++k)
        {
            const std::vector<RunTuple> shard = tuplesOf(scheduleRuns(config, {k, 3}));
            EXPECT_EQ(shard.size(), 2u * runCount);
            joined.insert(joined.end(), shard.begin(), shard.end());
        }
        std::sort(joined.begin(), joined.end());
        // the sorted union has no run twice and equals the whole schedule, seeds included
        EXPECT_EQ(std::adjacent_find(joined.begin(), joined.end()), joined.end());
        EXPECT_EQ(joined, all);
    }
}

TEST(ScheduleRuns, UnevenShardsAndMoreShardsThanRuns)
{
    // 2 x 3 x 1 = 6 runs in 4 shards: 2, 2, 1, 1; in 8 shards the last two are empty
    const BenchmarkConfig config = configOf(1);
    EXPECT_EQ(scheduleRuns(config, {1, 4}).size(), 2u);
    EXPECT_EQ(scheduleRuns(config, {2, 4}).size(), 2u);
    EXPECT_EQ(scheduleRuns(config, {3, 4}).size(), 1u);
    EXPECT_EQ(scheduleRuns(config, {4, 4}).size(), 1u);
    EXPECT_EQ(scheduleRuns(config, {6, 8}).size(), 1u);
    EXPECT_TRUE(scheduleRuns(config, {7, 8}).empty());
    EXPECT_TRUE(scheduleRuns(config, {8, 8}).empty());
}
