/* Pieces of JSON text for the result writers. */
#pragma once

#include <string>

namespace ompl_mm
{
    /** text as a JSON string literal, quotes included, with ", \ and control characters escaped. */
    std::string jsonQuoted(const std::string &text);
}  // namespace ompl_mm
