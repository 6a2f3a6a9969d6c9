/* The colours of ompl_phys's plan pictures, shared by the SVG and the 3-D page so both read alike. */
#pragma once

#include <cstddef>

namespace ompl_phys
{
    /** Fixed bodies. */
    constexpr const char *FIXED_COLOUR = "#666666";
    /** The robot and its trajectory. */
    constexpr const char *ROBOT_COLOUR = "#1f77b4";
    /** The goal disc. */
    constexpr const char *GOAL_COLOUR = "#2ca02c";
    /** The robot's course while it moves no body (the colour of MOPL's transit). */
    constexpr const char *TRANSIT_COLOUR = "#1f77b4";
    /** The robot's course while it moves a body (the colour of MOPL's push). */
    constexpr const char *PUSH_COLOUR = "#d62728";
    /** The floor. */
    constexpr const char *FLOOR_COLOUR = "#f4f1ea";

    /** The colour of movable body number i (0 for the first), from a palette that avoids the robot's. */
    const char *bodyColour(std::size_t i);
}  // namespace ompl_phys
