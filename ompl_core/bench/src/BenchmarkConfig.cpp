#include "ompl_core/bench/BenchmarkConfig.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/NumberText.h"
#include "ompl_core/io/TextFormat.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace ompl_core
{
    namespace
    {
        /** The longest time limit a config may set, seconds: a day per run. */
        constexpr double MAX_CONFIG_TIME_LIMIT = 86400.0;
        /** The largest memory limit, MB: 1 TiB. */
        constexpr double MAX_MEMORY_LIMIT = 1048576.0;

        std::string trimmed(const std::string &text)
        {
            const std::size_t first = text.find_first_not_of(" \t\r");
            if (first == std::string::npos)
                return "";
            return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
        }

        /** Letters, digits, '_', '-' and '.': names that survive the log's line format and the
            database's columns. */
        bool isPlainName(const std::string &name)
        {
            return !name.empty() && std::all_of(name.begin(), name.end(),
                                                [](char c) {
                                                    return std::isalnum(static_cast<unsigned char>(c)) ||
                                                           c == '_' || c == '-' || c == '.';
                                                });
        }

        /** One "key = value" line of a section. */
        struct Entry
        {
            std::string key;
            std::string value;
            SourceLocation where;
        };

        class ConfigParser
        {
        public:
            explicit ConfigParser(std::string file) : file_(std::move(file))
            {
                config_.file = file_;
                folder_ = std::filesystem::path(file_).parent_path();
            }

            BenchmarkConfig parse(const std::string &text)
            {
                // a byte-order mark, as some Windows editors write, is no part of the first line
                const std::string bom = "\xEF\xBB\xBF";
                std::istringstream in(text.compare(0, bom.size(), bom) == 0 ? text.substr(bom.size()) : text);
                std::string line;
                int number = 0;
                while (std::getline(in, line))
                {
                    ++number;
                    const std::string content = trimmed(line.substr(0, line.find('#')));
                    if (content.empty())
                        continue;
                    const SourceLocation where{file_, number};
                    if (content.front() == '[')
                        startSection(content, where);
                    else
                        readEntry(content, where);
                }
                finish();
                return config_;
            }

        private:
            void startSection(const std::string &content, const SourceLocation &where)
            {
                if (content.back() != ']')
                    throw InputError(where, "malformed section header '" + content + "' (expected [name])");
                section_ = trimmed(content.substr(1, content.size() - 2));
                if (section_ == "problem")
                {
                    config_.problems.emplace_back();
                    config_.problems.back().where = where;
                }
                else if (section_ == "benchmark" || section_ == "planner")
                {
                    const auto first = sectionLines_.find(section_);
                    if (first != sectionLines_.end())
                        throw InputError(where, "section [" + section_ + "] given twice (first at line " +
                                                    std::to_string(first->second) + ")");
                    sectionLines_[section_] = where.line;
                }
                else
                    throw InputError(where, "unknown section [" + section_ +
                                                "] (known: [problem], [benchmark], [planner])");
                keyLines_.clear();
            }

            void readEntry(const std::string &content, const SourceLocation &where)
            {
                const std::size_t equals = content.find('=');
                if (equals == std::string::npos)
                    throw InputError(where, "expected 'key = value', got '" + content + "'");
                const Entry entry{trimmed(content.substr(0, equals)), trimmed(content.substr(equals + 1)),
                                  where};
                if (entry.key.empty())
                    throw InputError(where, "a key is missing before '='");
                if (section_.empty())
                    throw InputError(where, "key '" + entry.key + "' is outside any section");
                if (section_ == "planner")
                    return readPlannerEntry(entry);
                const auto [first, isNew] = keyLines_.emplace(entry.key, where.line);
                if (!isNew)
                    throw InputError(where, "'" + entry.key +
                                                "' given twice in this section (first at line " +
                                                std::to_string(first->second) + ")");
                if (section_ == "problem")
                    readProblemEntry(entry);
                else
                    readBenchmarkEntry(entry);
            }

            void readProblemEntry(const Entry &entry)
            {
                BenchmarkProblem &problem = config_.problems.back();
                if (entry.key == "name")
                {
                    if (!isPlainName(entry.value))
                        throw InputError(entry.where, "problem name '" + entry.value +
                                                          "' must be letters, digits, '_', '-' or '.'");
                    problem.name = entry.value;
                }
                else if (entry.key == "scene")
                {
                    if (entry.value.empty())
                        throw InputError(entry.where, "scene needs a file name");
                    problem.scene = (folder_ / entry.value).lexically_normal().string();
                    problem.sceneWhere = entry.where;
                }
                else if (entry.key == "time_limit")
                    problem.timeLimit = timeLimit(entry);
                else
                    problem.parameters.push_back({entry.key, entry.value, entry.where});
            }

            void readBenchmarkEntry(const Entry &entry)
            {
                if (entry.key == "time_limit")
                    config_.timeLimit = timeLimit(entry);
                else if (entry.key == "mem_limit")
                    config_.memoryLimit = number(entry, 1.0, MAX_MEMORY_LIMIT);
                else if (entry.key == "run_count")
                    config_.runCount = static_cast<unsigned int>(wholeNumber(entry, 1, MAX_RUN_COUNT));
                else if (entry.key == "output")
                {
                    if (entry.value.empty())
                        throw InputError(entry.where, "output needs a folder");
                    config_.output = (folder_ / entry.value).lexically_normal().string();
                }
                else if (entry.key == "save_paths")
                    config_.savedPaths = savedPaths(entry);
                else if (entry.key == "simplify")
                    config_.simplify = flag(entry);
                else if (entry.key == "simulate")
                    config_.simulate = flag(entry);
                else if (entry.key == "seed")
                    config_.seed = static_cast<std::uint32_t>(wholeNumber(entry, 1, 4294967295.0));
                else
                    throw InputError(entry.where,
                                     "unknown key '" + entry.key +
                                         "' in [benchmark] (known: time_limit, mem_limit, run_count, "
                                         "output, save_paths, simplify, simulate, seed)");
            }

            void readPlannerEntry(const Entry &entry)
            {
                const std::size_t dot = entry.key.find('.');
                if (dot == std::string::npos)
                {
                    if (!entry.value.empty())
                        throw InputError(entry.where, "planner '" + entry.key +
                                                          "=' takes no value; set its "
                                                          "parameters with " +
                                                          entry.key + ".NAME=VALUE");
                    if (!isPlainName(entry.key))
                        throw InputError(entry.where, "planner name '" + entry.key +
                                                          "' must be letters, digits, '_', '-' or '.'");
                    config_.planners.push_back({entry.key, entry.key, {}, entry.where});
                    return;
                }
                const std::string type = entry.key.substr(0, dot);
                const std::string parameter = entry.key.substr(dot + 1);
                auto latest = std::find_if(config_.planners.rbegin(), config_.planners.rend(),
                                           [&](const BenchmarkPlanner &p) { return p.type == type; });
                if (latest == config_.planners.rend())
                    throw InputError(entry.where, "'" + entry.key + "' names no planner: add one with '" +
                                                      type + "=' on a line before");
                if (parameter.empty())
                    throw InputError(entry.where, "'" + entry.key + "' names no parameter");
                if (parameter == "name")
                {
                    if (!isPlainName(entry.value))
                        throw InputError(entry.where, "planner label '" + entry.value +
                                                          "' must be letters, digits, '_', '-' or '.'");
                    latest->label = entry.value;
                }
                else
                    latest->parameters.push_back({parameter, entry.value, entry.where});
            }

            void finish()
            {
                const SourceLocation wholeFile{file_, 0};
                if (config_.problems.empty())
                    throw InputError(wholeFile, "no [problem] section");
                std::map<std::string, int> names;
                for (const BenchmarkProblem &problem : config_.problems)
                {
                    if (problem.name.empty())
                        throw InputError(problem.where, "[problem] without a name");
                    if (problem.scene.empty())
                        throw InputError(problem.where, "[problem] '" + problem.name + "' without a scene");
                    const auto [first, isNew] = names.emplace(problem.name, problem.where.line);
                    if (!isNew)
                        throw InputError(problem.where, "problem name '" + problem.name +
                                                            "' given twice (first at line " +
                                                            std::to_string(first->second) + ")");
                }
                if (config_.planners.empty())
                    throw InputError(wholeFile, "no planner: list some in a [planner] section");
                std::map<std::string, const BenchmarkPlanner *> labels;
                for (const BenchmarkPlanner &planner : config_.planners)
                {
                    const auto [first, isNew] = labels.emplace(planner.label, &planner);
                    if (!isNew)
                        throw InputError(planner.where, "two planners are labelled '" + planner.label +
                                                            "' (the other at line " +
                                                            std::to_string(first->second->where.line) +
                                                            "): give one a label with " + planner.type +
                                                            ".name=LABEL");
                }
                if (config_.output.empty())
                    config_.output = folder_.empty() ? "." : folder_.string();
            }

            double number(const Entry &entry, double low, double high) const
            {
                const std::optional<double> value = parseNumber(entry.value);
                if (!value)
                    throw InputError(entry.where,
                                     "'" + entry.key + "' must be a number, got '" + entry.value + "'");
                if (*value < low || *value > high)
                    throw InputError(entry.where, "'" + entry.key + "' must be in [" + exactText(low) + ", " +
                                                      exactText(high) + "], got " + entry.value);
                return *value;
            }

            double wholeNumber(const Entry &entry, double low, double high) const
            {
                const double value = number(entry, low, high);
                if (value != std::floor(value))
                    throw InputError(entry.where,
                                     "'" + entry.key + "' must be a whole number, got " + entry.value);
                return value;
            }

            double timeLimit(const Entry &entry) const
            {
                const std::optional<double> value = parseNumber(entry.value);
                if (!value)
                    throw InputError(entry.where, "'time_limit' must be a number, got '" + entry.value + "'");
                if (!(*value > 0.0 && *value <= MAX_CONFIG_TIME_LIMIT))
                    throw InputError(entry.where, "'time_limit' must be in (0, " +
                                                      exactText(MAX_CONFIG_TIME_LIMIT) + "], got " +
                                                      entry.value);
                return *value;
            }

            bool flag(const Entry &entry) const
            {
                if (entry.value == "1" || entry.value == "true")
                    return true;
                if (entry.value == "0" || entry.value == "false")
                    return false;
                throw InputError(entry.where, "'" + entry.key + "' must be 0, 1, true or false, got '" +
                                                  entry.value + "'");
            }

            SavedPaths savedPaths(const Entry &entry) const
            {
                if (entry.value == "none")
                    return SavedPaths::None;
                if (entry.value == "all")
                    return SavedPaths::All;
                if (entry.value == "shortest")
                    return SavedPaths::Shortest;
                throw InputError(entry.where,
                                 "'save_paths' must be none, all or shortest, got '" + entry.value + "'");
            }

            std::string file_;
            std::filesystem::path folder_;
            BenchmarkConfig config_;
            std::string section_;                      ///< the current section, "" before the first
            std::map<std::string, int> sectionLines_;  ///< [benchmark] and [planner]: their lines
            std::map<std::string, int> keyLines_;      ///< keys of the current section: their lines
        };
    }  // namespace

    BenchmarkConfig parseBenchmarkConfig(const std::string &text, const std::string &file)
    {
        return ConfigParser(file).parse(text);
    }

    BenchmarkConfig loadBenchmarkConfig(const std::string &path)
    {
        return parseBenchmarkConfig(readInputFile(path, "benchmark config"), path);
    }
}  // namespace ompl_core
