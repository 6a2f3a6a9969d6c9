/* Seeding OMPL's random numbers for one run among many in a process. */
#pragma once

#include <cstdint>

namespace ompl_core
{
    /** Seeds OMPL's generator of seeds, so every generator made afterwards follows from seed, also
        after others were made: OMPL then reports that earlier generators keep their sequences, which
        is silenced here, since a run that makes all its objects afresh needs no more. */
    void reseedOmpl(std::uint32_t seed);
}  // namespace ompl_core
