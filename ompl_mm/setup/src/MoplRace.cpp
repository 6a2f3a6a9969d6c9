#include "ompl_mm/setup/MoplRace.h"

#include <ompl/util/Exception.h>

#include <atomic>
#include <exception>
#include <limits>
#include <thread>

namespace ompl_mm
{
    std::uint_fast32_t MoplRace::seedOf(std::uint_fast32_t seed, unsigned int index)
    {
        // apart by the golden ratio's step (Weyl sequence), within OMPL's positive 32-bit seeds
        const std::uint32_t step = 0x9E3779B9u;
        const std::uint32_t mixed =
            static_cast<std::uint32_t>(seed) + static_cast<std::uint32_t>(index) * step;
        return mixed == 0 ? 1 : mixed;
    }

    int MoplRace::solve(const std::vector<ManipulationSetup *> &setups,
                        const ompl::base::PlannerTerminationCondition &ptc)
    {
        const auto count = static_cast<unsigned int>(setups.size());
        if (count == 0 || count > MAX_SEARCHES)
            throw ompl::Exception("MoplRace", "a race needs 1 to " + std::to_string(MAX_SEARCHES) +
                                                  " searches, got " + std::to_string(count));
        std::vector<MOPL *> searches;
        for (ManipulationSetup *setup : setups)
        {
            const std::shared_ptr<MOPL> mopl = setup->mopl();
            if (!mopl)
                throw ompl::Exception("MoplRace",
                                      "every search must be MOPL, got " + setup->getPlanner()->getName());
            searches.push_back(mopl.get());
            // here, not in the threads: setting up draws from OMPL's global seed sequence
            setup->setup();
        }

        // a search's rank: iterations first, index second; the best rank of a solution so far
        const auto rank = [count](std::uint64_t iterations, unsigned int index)
        { return iterations * count + index; };
        std::atomic<std::uint64_t> best{std::numeric_limits<std::uint64_t>::max()};
        std::vector<char> solved(count, 0);
        std::vector<std::exception_ptr> failures(count);
        const auto run = [&](unsigned int index)
        {
            try
            {
                const MOPL &search = *searches[index];
                // MOPL polls once per iteration (and within its steps): a search whose current
                // iteration already ranks behind a solution cannot win
                const ompl::base::PlannerTerminationCondition beaten(
                    [&, index]
                    { return ptc() || rank(search.statistics().iterations, index) > best.load(); });
                if (setups[index]->solve(beaten) == ompl::base::PlannerStatus::EXACT_SOLUTION)
                {
                    solved[index] = 1;
                    const std::uint64_t mine = rank(search.statistics().iterations, index);
                    std::uint64_t current = best.load();
                    while (mine < current && !best.compare_exchange_weak(current, mine))
                    {
                    }
                }
            }
            catch (...)
            {
                failures[index] = std::current_exception();
            }
        };
        std::vector<std::thread> threads;
        for (unsigned int index = 1; index < count; ++index)
            threads.emplace_back(run, index);
        run(0);
        for (std::thread &thread : threads)
            thread.join();
        for (const std::exception_ptr &failure : failures)
            if (failure)
                std::rethrow_exception(failure);

        int winner = -1;
        for (unsigned int index = 0; index < count; ++index)
            if (solved[index] && rank(searches[index]->statistics().iterations, index) == best.load())
                winner = static_cast<int>(index);
        return winner;
    }
}  // namespace ompl_mm
