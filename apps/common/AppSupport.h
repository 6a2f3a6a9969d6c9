/* What the command-line apps share: checked seeds and time limits, output files opened before
   planning, and the mapping of failures to exit codes (2 for bad input, with the message on
   stderr prefixed by the app's name). */
#pragma once

#include "ompl_mm/scene/InputError.h"

#include <boost/program_options.hpp>

#include <fstream>
#include <functional>
#include <iostream>
#include <string>

namespace ompl_mm::apps
{
    /** @throws InputError unless seed is in [1, 2^32 - 1] and a given time limit is positive. */
    inline void checkSeedAndTimeLimit(long long seed, bool timeLimitGiven, double timeLimit)
    {
        if (seed < 1 || seed > 4294967295LL)
            throw InputError("--seed must be in [1, 4294967295], got " + std::to_string(seed));
        if (timeLimitGiven && !(timeLimit > 0.0))
            throw InputError("--time-limit must be positive");
    }

    /** An output file, or a closed stream for an empty path. @throws InputError when it cannot be written. */
    inline std::ofstream openOutput(const std::string &path)
    {
        std::ofstream out;
        if (path.empty())
            return out;
        out.open(path);
        if (!out)
            throw InputError(path + ": cannot write file");
        return out;
    }

    /** Runs body and turns bad command lines and bad input into exit code 2 with a message. */
    inline int runApp(const char *name, const std::function<int()> &body)
    {
        try
        {
            return body();
        }
        catch (const boost::program_options::error &e)
        {
            std::cerr << name << ": " << e.what() << " (see --help)\n";
        }
        catch (const ompl::Exception &e)
        {
            std::cerr << name << ": " << e.what() << '\n';
        }
        return 2;
    }
}  // namespace ompl_mm::apps
