/* Numbers written by users, read strictly: the whole token, finite, whatever the C locale. */
#pragma once

#include <optional>
#include <string_view>

namespace ompl_core
{
    /** A finite decimal number filling the whole token ("1", "-0.5", "+2e-3"), else nothing.
        Independent of the C locale. */
    std::optional<double> parseNumber(std::string_view token);

    /** A number in radians, or in degrees when followed by "deg" ("90deg"), converted to radians;
        nothing when malformed or not finite. */
    std::optional<double> parseAngle(std::string_view token);
}  // namespace ompl_core
