#include "ompl_core/run/RunRecord.h"

#include "ompl_core/io/TextFormat.h"

#include <ompl/util/Exception.h>

#include <cmath>
#include <iomanip>
#include <locale>
#include <sstream>

namespace ompl_core
{
    namespace
    {
        /** Significant digits of numbers in JSON results. */
        constexpr int JSON_DIGITS = 10;

        std::string jsonNumber(double value)
        {
            if (!std::isfinite(value))
                return "null";
            std::ostringstream out;
            out.imbue(std::locale::classic());
            out << std::setprecision(JSON_DIGITS) << value;
            return out.str();
        }

        void writeRecord(std::ostream &out, const RunRecord &record, const std::string &indent);

        /** A value on one line, except nested records, which get a line per entry. */
        void writeValue(std::ostream &out, const RunRecord::Entry &entry, const std::string &indent)
        {
            struct Visitor
            {
                std::ostream &out;
                const std::string &indent;
                void operator()(double v) const { out << jsonNumber(v); }
                void operator()(std::uint64_t v) const { out << v; }
                void operator()(bool v) const { out << (v ? "true" : "false"); }
                void operator()(const std::string &v) const { out << jsonQuoted(v); }
                void operator()(const std::vector<std::string> &v) const
                {
                    out << '[';
                    for (std::size_t i = 0; i < v.size(); ++i)
                        out << (i ? ", " : "") << jsonQuoted(v[i]);
                    out << ']';
                }
                void operator()(const RunRecord &v) const { writeRecord(out, v, indent); }
            };
            std::visit(Visitor{out, indent}, entry.value);
        }

        void writeEntries(std::ostream &out, const RunRecord &record, const std::string &indent, bool first)
        {
            for (const RunRecord::Entry &entry : record.entries())
            {
                out << (first ? "" : ",") << '\n' << indent << "  " << jsonQuoted(entry.key) << ": ";
                writeValue(out, entry, indent + "  ");
                first = false;
            }
        }

        void writeRecord(std::ostream &out, const RunRecord &record, const std::string &indent)
        {
            out << '{';
            writeEntries(out, record, indent, true);
            out << '\n' << indent << '}';
        }
    }  // namespace

    RunRecord &RunRecord::add(Entry entry)
    {
        if (entry.key.empty() || entry.key.find('.') != std::string::npos)
            throw ompl::Exception("RunRecord",
                                  "bad key '" + entry.key + "': keys are non-empty and hold no '.'");
        for (const Entry &existing : entries_)
            if (existing.key == entry.key)
                throw ompl::Exception("RunRecord", "key '" + entry.key + "' is already used");
        entries_.push_back(std::move(entry));
        return *this;
    }

    RunRecord &RunRecord::addNumber(const std::string &key, double value)
    {
        return add({key, value});
    }

    RunRecord &RunRecord::addCount(const std::string &key, std::uint64_t value)
    {
        return add({key, value});
    }

    RunRecord &RunRecord::addFlag(const std::string &key, bool value)
    {
        return add({key, value});
    }

    RunRecord &RunRecord::addText(const std::string &key, const std::string &value)
    {
        return add({key, value});
    }

    RunRecord &RunRecord::addTexts(const std::string &key, const std::vector<std::string> &values)
    {
        return add({key, values});
    }

    RunRecord &RunRecord::addRecord(const std::string &key, const RunRecord &value)
    {
        return add({key, value});
    }

    const RunRecord::Entry *RunRecord::find(const std::string &path) const
    {
        const std::size_t dot = path.find('.');
        const std::string key = path.substr(0, dot);
        for (const Entry &entry : entries_)
        {
            if (entry.key != key)
                continue;
            if (dot == std::string::npos)
                return &entry;
            const auto *nested = std::get_if<RunRecord>(&entry.value);
            return nested ? nested->find(path.substr(dot + 1)) : nullptr;
        }
        return nullptr;
    }

    RunResult runResult(const RunDescription &run, const ompl::base::ProblemDefinition &pdef,
                        const ompl::base::PlannerStatus &status, double time)
    {
        RunResult result;
        result.run = run;
        result.solved = pdef.hasExactSolution();
        result.approximate = pdef.hasApproximateSolution();
        result.status = status.asString();
        result.time = time;
        return result;
    }

    void writeRunJson(std::ostream &out, const RunResult &result)
    {
        RunRecord header;
        header.addText("scene", result.run.scene)
            .addText("planner", result.run.planner)
            .addCount("seed", result.run.seed)
            .addNumber("time_limit_s", result.run.timeLimit)
            .addFlag("solved", result.solved)
            .addFlag("approximate", result.approximate)
            .addText("status", result.status)
            .addNumber("time_s", result.time);
        out << '{';
        writeEntries(out, header, "", true);
        writeEntries(out, result.details, "", false);
        out << "\n}\n";
    }
}  // namespace ompl_core
