#include "ompl_core/bench/RunSchedule.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/NumberText.h"
#include "ompl_core/run/Fnv1aHash.h"

#include <cmath>
#include <optional>

namespace ompl_core
{
    namespace
    {
        /** The number's four bytes, least significant first, whatever the machine's byte order. */
        std::string bytesOf(std::uint32_t value)
        {
            std::string bytes(4, '\0');
            for (std::size_t i = 0; i < 4; ++i)
                bytes[i] = static_cast<char>((value >> (8 * i)) & 0xffu);
            return bytes;
        }
    }  // namespace

    Shard parseShard(const std::string &text)
    {
        const std::string where = "command line option --shard: ";
        const std::size_t slash = text.find('/');
        const std::optional<double> k = parseNumber(text.substr(0, slash));
        const std::optional<double> n =
            slash == std::string::npos ? std::nullopt : parseNumber(text.substr(slash + 1));
        if (!k || !n || *k != std::floor(*k) || *n != std::floor(*n))
            throw InputError(where + "expected K/N with whole numbers, got '" + text + "'");
        if (*n < 1.0 || *n > MAX_SHARDS || *k < 1.0 || *k > *n)
            throw InputError(where + "'" + text + "' needs 1 <= K <= N <= " + std::to_string(MAX_SHARDS));
        return {static_cast<unsigned int>(*k), static_cast<unsigned int>(*n)};
    }

    std::uint32_t runSeed(std::uint32_t configSeed, const std::string &problem,
                          const std::string &plannerLabel, unsigned int index)
    {
        // the zero bytes keep "ab" + "c" apart from "a" + "bc"
        const std::uint64_t hash =
            fnv1a64(bytesOf(index),
                    fnv1a64(plannerLabel + '\0', fnv1a64(problem + '\0', fnv1a64(bytesOf(configSeed)))));
        const auto seed = static_cast<std::uint32_t>(hash ^ (hash >> 32));
        return seed == 0 ? 1 : seed;  // OMPL takes 0 as "no seed"
    }

    std::vector<ScheduledRun> scheduleRuns(const BenchmarkConfig &config, const Shard &shard)
    {
        std::vector<ScheduledRun> runs;
        std::size_t position = 0;
        for (std::size_t p = 0; p < config.problems.size(); ++p)
            for (std::size_t q = 0; q < config.planners.size(); ++q)
                for (unsigned int k = 0; k < config.runCount; ++k, ++position)
                    if (position % shard.count == shard.index - 1)
                        runs.push_back(
                            {p, q, k,
                             runSeed(config.seed, config.problems[p].name, config.planners[q].label, k)});
        return runs;
    }
}  // namespace ompl_core
