/* Pieces of JSON and XML (SVG) text for the result writers. */
#pragma once

#include <ostream>
#include <string>

namespace ompl_mm
{
    struct RunDescription;

    /** text as a JSON string literal, quotes included, with ", \ and control characters escaped. */
    std::string jsonQuoted(const std::string &text);

    /** text with XML's special characters as entities (&amp; &lt; &gt; &quot; &apos;). */
    std::string xmlEscaped(const std::string &text);

    /** Opens a result object with the keys every app writes: scene, planner, seed, time_limit_s,
        solved, status, time_s (each line ends with a comma, so more keys follow). */
    void writeRunHeader(std::ostream &out, const RunDescription &run, bool solved, const std::string &status,
                        double time);
}  // namespace ompl_mm
