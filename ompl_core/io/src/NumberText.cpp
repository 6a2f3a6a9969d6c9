#include "ompl_core/io/NumberText.h"

#include <charconv>
#include <cmath>

namespace ompl_core
{
    namespace
    {
        constexpr std::string_view DEGREE_SUFFIX = "deg";
        constexpr double RADIANS_PER_DEGREE = 3.14159265358979323846 / 180.0;
    }  // namespace

    std::optional<double> parseNumber(std::string_view token)
    {
        // from_chars rejects a leading '+', which users reasonably write
        if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-')
            token.remove_prefix(1);
        double value = 0.0;
        const char *end = token.data() + token.size();
        const auto [ptr, ec] = std::from_chars(token.data(), end, value);
        if (ec != std::errc() || ptr != end || !std::isfinite(value))
            return std::nullopt;
        return value;
    }

    std::optional<double> parseAngle(std::string_view token)
    {
        if (token.size() > DEGREE_SUFFIX.size() &&
            token.substr(token.size() - DEGREE_SUFFIX.size()) == DEGREE_SUFFIX)
        {
            const std::optional<double> degrees =
                parseNumber(token.substr(0, token.size() - DEGREE_SUFFIX.size()));
            if (!degrees)
                return std::nullopt;
            return *degrees * RADIANS_PER_DEGREE;
        }
        return parseNumber(token);
    }
}  // namespace ompl_core
