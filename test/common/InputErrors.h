// Test helpers shared by the tests of all libraries: the message of an exception, and text checks.
#pragma once

#include "ompl_core/io/InputError.h"

#include <string>
#include <utility>

namespace ompl_core::test
{
    /** The message of the Error that f() throws, or "" when it throws none. */
    template <typename Error, typename F>
    std::string messageOf(F &&f)
    {
        try
        {
            f();
        }
        catch (const Error &e)
        {
            return e.what();
        }
        return "";
    }

    /** The message of the InputError that f() throws, or "" when it throws none. */
    template <typename F>
    std::string inputErrorOf(F &&f)
    {
        return messageOf<InputError>(std::forward<F>(f));
    }

    /** The message of the ompl::Exception (InputError included) that f() throws, or "". */
    template <typename F>
    std::string exceptionOf(F &&f)
    {
        return messageOf<ompl::Exception>(std::forward<F>(f));
    }

    /** The fault a Setup (ManipulationSetup, PhysicsSetup) finds in scene before planning: the
        InputError message of building it, else the message of its goalFault(), else "". */
    template <typename Setup, typename Scene>
    std::string setupFaultOf(const Scene &scene)
    {
        std::string goalFault;
        const std::string built = inputErrorOf(
            [&]
            {
                Setup setup(scene);
                if (setup.goalFault())
                    goalFault = setup.goalFault()->what();
            });
        return built.empty() ? goalFault : built;
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
