#pragma once

#include <ompl/base/PlannerStatus.h>
#include <ompl/base/ProblemDefinition.h>

#include <cstdint>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace ompl_core
{
    /** What a run was asked to do. */
    struct RunDescription
    {
        std::string scene;      ///< scene name
        std::string planner;    ///< planner name, as in the planner registry
        std::uint32_t seed{0};  ///< random seed
        double timeLimit{0.0};  ///< seconds
    };

    /** Named values in a fixed order: numbers, counts, flags, texts, lists of texts and nested
        records (such as "stats" with its times and counters). Keys are unique within a record.
        A record holds its values, nested records included, by value. */
    class RunRecord
    {
    public:
        struct Entry;

        /** Appends a number; non-finite ones are written to JSON as null.
            @throws ompl::Exception when key is empty, holds a '.', or is already used. */
        RunRecord &addNumber(const std::string &key, double value);
        /** Appends a count. @throws ompl::Exception for a bad or used key, as addNumber(). */
        RunRecord &addCount(const std::string &key, std::uint64_t value);
        /** Appends a flag. @throws ompl::Exception for a bad or used key, as addNumber(). */
        RunRecord &addFlag(const std::string &key, bool value);
        /** Appends a text. @throws ompl::Exception for a bad or used key, as addNumber(). */
        RunRecord &addText(const std::string &key, const std::string &value);
        /** Appends a list of texts. @throws ompl::Exception for a bad or used key, as addNumber(). */
        RunRecord &addTexts(const std::string &key, const std::vector<std::string> &values);
        /** Appends a copy of a nested record. @throws ompl::Exception for a bad or used key, as
            addNumber(). */
        RunRecord &addRecord(const std::string &key, const RunRecord &value);

        /** The entries in the order they were added. */
        const std::vector<Entry> &entries() const { return entries_; }
        /** Whether nothing was added. */
        bool empty() const { return entries_.empty(); }

        /** The entry at a dotted path ("stats.iterations"), or nullptr. The pointer is valid until
            the record is changed or destroyed. */
        const Entry *find(const std::string &path) const;

    private:
        /** @throws ompl::Exception when key is empty, holds a '.', or is already used. */
        RunRecord &add(Entry entry);

        std::vector<Entry> entries_;
    };

    /** One named value of a RunRecord. */
    struct RunRecord::Entry
    {
        std::string key;  ///< unique within its record, non-empty, no '.'
        /** The value: number, count, flag, text, list of texts or nested record. */
        std::variant<double, std::uint64_t, bool, std::string, std::vector<std::string>, RunRecord> value;
    };

    /** What one planning run was asked to do and what came of it, in one shape for every planner
        of both libraries: the apps write it as JSON (writeRunJson()), the benchmark scripts read
        that JSON, and benchmark logs take their run properties from it. */
    struct RunResult
    {
        RunDescription run;       ///< what the run was asked to do
        bool solved{false};       ///< an exact solution was found
        bool approximate{false};  ///< only an approximate solution was found
        std::string status;       ///< OMPL's PlannerStatus as text
        double time{0.0};         ///< planning time, seconds
        RunRecord details;        ///< the library's own values (statistics, path, metrics), in output order
    };

    /** The result every planner shares, without details: whether pdef holds an exact or only an
        approximate solution, the planner's status and its planning time (seconds). */
    RunResult runResult(const RunDescription &run, const ompl::base::ProblemDefinition &pdef,
                        const ompl::base::PlannerStatus &status, double time);

    /** Writes result as one JSON object: scene, planner, seed, time_limit_s, solved, approximate,
        status, time_s, then the details. Non-finite numbers are written as null. */
    void writeRunJson(std::ostream &out, const RunResult &result);
}  // namespace ompl_core
