/* Pieces of text for messages and for the result writers of both libraries. */
#pragma once

#include <string>
#include <vector>

namespace ompl_core
{
    /** text as a JSON string literal, quotes included, with `"`, `\` and control characters escaped
        (the latter as `\u00XX`). Other bytes, UTF-8 included, pass unchanged. */
    std::string jsonQuoted(const std::string &text);

    /** text with `&`, `<`, `>`, `"` and the apostrophe replaced by XML's entities (amp, lt, gt, quot,
        apos), for attribute values and element text. */
    std::string xmlEscaped(const std::string &text);

    /** A double as text that converts back to the same double (17 significant digits, "C"
    locale): for planner parameters and properties, where OMPL's toString keeps 6. */
    std::string exactText(double value);

    /** A double as short text for messages (6 significant digits, "C" locale): "0.001", "1e+08". */
    std::string formatNumber(double value);

    /** The names joined by ", " for messages ("known: a, b"), or whenEmpty when there are none. */
    std::string joinedNames(const std::vector<std::string> &names, const std::string &whenEmpty = "none");
}  // namespace ompl_core
