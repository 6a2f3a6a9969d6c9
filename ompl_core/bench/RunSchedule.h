/* Which runs a benchmark makes, with which seeds, and how they split into shards for many machines. */
#pragma once

#include "ompl_core/bench/BenchmarkConfig.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ompl_core
{
    /** The most shards a benchmark may be split into. */
    constexpr unsigned int MAX_SHARDS = 100000;

    /** Shard K of N (1-based): every N-th run of the whole schedule, starting at run K. */
    struct Shard
    {
        unsigned int index{1};  ///< K, in [1, count]
        unsigned int count{1};  ///< N
    };

    /** Reads "K/N" as given to --shard.
        @throws InputError naming the option unless K and N are whole numbers with 1 <= K <= N <=
        MAX_SHARDS. */
    Shard parseShard(const std::string &text);

    /** One run of a benchmark. */
    struct ScheduledRun
    {
        std::size_t problem{0};  ///< index into BenchmarkConfig::problems
        std::size_t planner{0};  ///< index into BenchmarkConfig::planners
        unsigned int index{0};   ///< repetition, 0-based
        std::uint32_t seed{1};   ///< runSeed() of the above
    };

    /** The seed of one run: a hash (FNV-1a) of the config's seed, the problem's name, the planner's
        label and the repetition, never 0. It depends on nothing else, so a run has the same seed
        in every shard and in every order. */
    std::uint32_t runSeed(std::uint32_t configSeed, const std::string &problem,
                          const std::string &plannerLabel, unsigned int index);

    /** The runs of shard among all of config's, which are ordered by problem, then planner, then
        repetition; the shards of one count together hold each run exactly once. */
    std::vector<ScheduledRun> scheduleRuns(const BenchmarkConfig &config, const Shard &shard = {});
}  // namespace ompl_core
