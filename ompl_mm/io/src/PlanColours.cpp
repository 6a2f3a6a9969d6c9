#include "ompl_mm/io/PlanColours.h"

#include <array>

namespace ompl_mm
{
    namespace
    {
        constexpr std::array<const char *, 10> OBJECT_PALETTE = {"#9467bd", "#8c564b", "#e377c2", "#bcbd22",
                                                                 "#17becf", "#393b79", "#637939", "#8c6d31",
                                                                 "#843c39", "#7b4173"};
    }  // namespace

    const char *primitiveColour(PrimitiveKind kind)
    {
        switch (kind)
        {
            case PrimitiveKind::Transit:
                return "#1f77b4";
            case PrimitiveKind::Push:
                return "#d62728";
            case PrimitiveKind::Pickup:
                return "#2ca02c";
            case PrimitiveKind::Transfer:
                return "#ff7f0e";
        }
        return "#000000";
    }

    const char *objectColour(unsigned int object)
    {
        return OBJECT_PALETTE[object % OBJECT_PALETTE.size()];
    }
}  // namespace ompl_mm
