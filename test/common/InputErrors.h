// Test helpers shared by the tests of both libraries: the message of an InputError, and text checks.
#pragma once

#include "ompl_core/io/InputError.h"

#include <string>

namespace ompl_core::test
{
    /** The message of the InputError that f() throws, or "" when it throws none. */
    template <typename F>
    std::string inputErrorOf(F &&f)
    {
        try
        {
            f();
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }

    /** True when text begins with prefix. */
    inline bool startsWith(const std::string &text, const std::string &prefix)
    {
        return text.compare(0, prefix.size(), prefix) == 0;
    }

    /** True when text contains part. */
    inline bool contains(const std::string &text, const std::string &part)
    {
        return text.find(part) != std::string::npos;
    }
}  // namespace ompl_core::test
