/* Benchmark experiments described in the cfg format of OMPL.app's ompl_benchmark. */
#pragma once

#include "ompl_core/io/SourceLocation.h"
#include "ompl_core/run/ParameterSetting.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ompl_core
{
    /** How many runs a config may ask for per planner and problem. */
    constexpr unsigned int MAX_RUN_COUNT = 1000000;

    /** Which solution paths a benchmark writes beside its log. */
    enum class SavedPaths
    {
        None,      ///< no path files
        All,       ///< one file per solved run
        Shortest,  ///< one file per problem and planner: its shortest solution
    };

    /** One planner instance of a config: a registered planner, its label in the log and its
        parameters. */
    struct BenchmarkPlanner
    {
        std::string type;                          ///< the registry's name ("mopl", "rrt")
        std::string label;                         ///< distinct name in the log; type by default
        std::vector<ParameterSetting> parameters;  ///< NAME.param=value lines, in order
        SourceLocation where;                      ///< the NAME= line
    };

    /** One [problem] section: a scene and the parameters every planner that declares them gets. */
    struct BenchmarkProblem
    {
        std::string name;                          ///< experiment name: letters, digits, '_', '-', '.'
        std::string scene;                         ///< scene file, resolved against the cfg's folder
        SourceLocation sceneWhere;                 ///< the scene= line
        std::optional<double> timeLimit;           ///< seconds; the [benchmark] limit when unset
        std::vector<ParameterSetting> parameters;  ///< other keys, in order
        SourceLocation where;                      ///< the [problem] line
    };

    /** A whole config: one or more problems, each planned by every planner. */
    struct BenchmarkConfig
    {
        std::string file;                         ///< the cfg file as given
        std::vector<BenchmarkProblem> problems;   ///< in file order
        std::optional<double> timeLimit;          ///< seconds per run; the scene's limit when unset
        double memoryLimit{4096.0};               ///< MB per run (OMPL's Benchmark default)
        unsigned int runCount{100};               ///< runs per planner and problem
        std::string output;                       ///< folder of the logs; the cfg's folder by default
        SavedPaths savedPaths{SavedPaths::None};  ///< solution paths written beside the logs
        bool simplify{true};                      ///< Benchmark's simplification of geometric paths
        bool simulate{false};                     ///< ompl_mm scenes' solutions executed in physics too
        std::uint32_t seed{1};                    ///< from which every run's seed derives
        std::vector<BenchmarkPlanner> planners;   ///< in file order
    };

    /** Reads a config: INI sections [problem] (repeatable; name, scene, time_limit, and any other
        key as a planner parameter), [benchmark] (time_limit, mem_limit, run_count, output,
        save_paths, simplify, simulate, seed) and [planner] (NAME= adds an instance of a registered planner;
        NAME.param=value sets a parameter of the latest NAME, NAME.name=label names it). '#' starts
        a comment. Whether planners and parameters exist is left to the scene's registry.
        @throws InputError naming file:line for an unknown section or key, a key outside any
        section, a malformed line, a value of the wrong kind or out of range, a key given twice in
        [problem] or [benchmark], [benchmark] or [planner] given twice, a missing name or scene, or
        two planners with one label; naming the file for a config without a problem or a planner.
        In [planner], a later NAME.param line for the same planner wins. */
    BenchmarkConfig loadBenchmarkConfig(const std::string &path);

    /** Reads a config from text; file names it in messages and resolves relative paths.
        @throws InputError as loadBenchmarkConfig(). */
    BenchmarkConfig parseBenchmarkConfig(const std::string &text, const std::string &file);
}  // namespace ompl_core
