/* The command line of a benchmark program over physics scene files: its named options, and the scene
   files as every positional argument. */
#pragma once

#include <boost/program_options.hpp>

#include <iostream>
#include <string>
#include <vector>

namespace benchmarks
{
    /** Reads argc/argv into the variables of named (which should offer "help,h") and the scene files
        into scenes. After --help it prints usage (its first lines: usage, what the program does, its
        exit status) and the named options, and returns false: the program should then exit with 0.
        @throws boost::program_options::error for a malformed command line or no scene file. */
    inline bool parseSceneFilesCommandLine(int argc, char **argv,
                                           const boost::program_options::options_description &named,
                                           const std::string &usage, std::vector<std::string> &scenes)
    {
        namespace po = boost::program_options;
        po::options_description hidden;
        hidden.add_options()("scene", po::value(&scenes));
        po::options_description all;
        all.add(named).add(hidden);
        po::positional_options_description positionals;
        positionals.add("scene", -1);
        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(all).positional(positionals).run(), vm);
        po::notify(vm);
        if (vm.count("help"))
        {
            std::cout << usage << "\n\n" << named;
            return false;
        }
        if (scenes.empty())
            throw po::error("no scene file given");
        return true;
    }
}  // namespace benchmarks
