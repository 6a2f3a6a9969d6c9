#include "ompl_core/run/GlobalSeed.h"

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

namespace ompl_core
{
    void reseedOmpl(std::uint32_t seed)
    {
        ompl::msg::noOutputHandler();
        ompl::RNG::setSeed(seed);
        ompl::msg::restorePreviousOutputHandler();
    }
}  // namespace ompl_core
