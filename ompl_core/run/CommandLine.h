/* Reading the project's command lines: named options and one positional argument (a file). */
#pragma once

#include <boost/program_options.hpp>

#include <string>

namespace ompl_core
{
    /** Parses argv with the named options and one positional argument, stored in positional (its
        name, for messages, is positionalName).
        @throws boost::program_options::error for an unknown option, a missing or bad value, or a
        second positional argument. */
    inline boost::program_options::variables_map parseCommandLine(
        int argc, const char *const *argv, const boost::program_options::options_description &named,
        const std::string &positionalName, std::string &positional)
    {
        namespace po = boost::program_options;
        po::options_description hidden;
        hidden.add_options()(positionalName.c_str(), po::value(&positional));
        po::options_description all;
        all.add(named).add(hidden);
        po::positional_options_description positionals;
        positionals.add(positionalName.c_str(), 1);
        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(all).positional(positionals).run(), vm);
        po::notify(vm);
        return vm;
    }
}  // namespace ompl_core
