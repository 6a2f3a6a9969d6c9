/* The exit status and message of a command-line program of the project, from what its body throws. */
#pragma once

#include "ompl_core/io/OutputFile.h"

#include <ompl/util/Exception.h>

#include <filesystem>
#include <iostream>
#include <string>

namespace ompl_core
{
    /** Runs body (which returns the exit status) and turns what it throws into a message on stderr
        prefixed with program and an exit status: 2 for a bad command line (CommandLineError, as
        boost::program_options::error, with a hint to --help) and for bad input (ompl::Exception,
        InputError included); 1 when an output could not be written (OutputError, or a filesystem
        error creating a folder). */
    template <typename CommandLineError, typename Body>
    int exitStatusOf(const std::string &program, Body &&body)
    {
        try
        {
            return body();
        }
        catch (const CommandLineError &e)
        {
            std::cerr << program << ": " << e.what() << " (see --help)\n";
        }
        catch (const ompl::Exception &e)
        {
            std::cerr << program << ": " << e.what() << '\n';
        }
        catch (const OutputError &e)
        {
            std::cerr << program << ": " << e.what() << '\n';
            return 1;
        }
        catch (const std::filesystem::filesystem_error &e)
        {
            std::cerr << program << ": " << e.what() << '\n';
            return 1;
        }
        return 2;
    }
}  // namespace ompl_core
