/* Pieces of JSON and XML text for the result writers of both libraries. */
#pragma once

#include <string>

namespace ompl_core
{
    /** text as a JSON string literal, quotes included, with ", \ and control characters escaped. */
    std::string jsonQuoted(const std::string &text);

    /** text with XML's special characters as entities (&amp; &lt; &gt; &quot; &apos;). */
    std::string xmlEscaped(const std::string &text);
}  // namespace ompl_core
