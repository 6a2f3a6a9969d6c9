#include "ompl_phys/io/PhysicsColours.h"

#include <array>

namespace ompl_phys
{
    const char *bodyColour(std::size_t i)
    {
        constexpr std::array<const char *, 7> PALETTE = {"#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
                                                         "#bcbd22", "#17becf", "#d62728"};
        return PALETTE[i % PALETTE.size()];
    }
}  // namespace ompl_phys
