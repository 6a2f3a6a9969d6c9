/* Seeding OMPL's random numbers for one run among many in a process. */
#pragma once

#include <cstdint>

namespace ompl_core
{
    /** Seeds OMPL's generator of seeds, so every generator made afterwards follows from seed, also
        after others were made: OMPL then reports that earlier generators keep their sequences, which
        is silenced here, since a run that makes all its objects afresh needs no more.

        A run is seeded twice: before its setup and planner are made, and again after setup(), right
        before solve(), so that whatever draws random numbers in between (ompl::tools::Benchmark
        samples states to describe the setup) does not shift the run's. The apps and the benchmark
        tool both do so, which is why a benchmark run is planned again by the app with its seed. */
    void reseedOmpl(std::uint32_t seed);
}  // namespace ompl_core
