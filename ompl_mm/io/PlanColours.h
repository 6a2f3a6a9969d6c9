/* The colours of ompl_mm's plan pictures, shared by the SVG and the 3-D page so both read alike. */
#pragma once

#include "ompl_mm/primitives/Trajectory.h"

namespace ompl_mm
{
    /** Fixed obstacles. */
    constexpr const char *OBSTACLE_COLOUR = "#555555";
    /** The 3-D page's floor slabs (obstacles at or under the lowest support surface). */
    constexpr const char *FLOOR_COLOUR = "#c9c9c4";
    /** Support surfaces. */
    constexpr const char *SURFACE_COLOUR = "#e2e2e2";
    /** The robot. */
    constexpr const char *ROBOT_COLOUR = "#333333";

    /** The tool path along a primitive of kind: transit blue, push red, pickup green, transfer
        orange. */
    const char *primitiveColour(PrimitiveKind kind);

    /** Object i's colour, from a palette that avoids the primitives' colours. */
    const char *objectColour(unsigned int object);
}  // namespace ompl_mm
