#include "ompl_core/bench/RunProperties.h"

#include "ompl_core/io/TextFormat.h"

#include <cmath>
#include <type_traits>

namespace ompl_core
{
    namespace
    {
        /** The record whose keys name their properties alone: the planner's statistics. */
        const std::string UNPREFIXED_RECORD = "stats";

        void add(ompl::tools::Benchmark::RunProperties &properties, const std::string &name,
                 const std::string &value)
        {
            properties.emplace(name, value);  // a value already there (the planner's own) stays
        }

        void addWithPrefix(const RunRecord &record, const std::string &prefix,
                           ompl::tools::Benchmark::RunProperties &properties)
        {
            for (const RunRecord::Entry &entry : record.entries())
            {
                const std::string name = prefix + entry.key;
                std::visit(
                    [&](const auto &value)
                    {
                        using T = std::decay_t<decltype(value)>;
                        if constexpr (std::is_same_v<T, double>)
                        {
                            if (std::isfinite(value))
                                add(properties, name + " REAL", exactText(value));
                        }
                        else if constexpr (std::is_same_v<T, std::uint64_t>)
                            add(properties, name + " INTEGER", std::to_string(value));
                        else if constexpr (std::is_same_v<T, bool>)
                            add(properties, name + " BOOLEAN", value ? "1" : "0");
                        else if constexpr (std::is_same_v<T, RunRecord>)
                            addWithPrefix(value, entry.key == UNPREFIXED_RECORD ? prefix : name + "_",
                                          properties);
                    },
                    entry.value);
            }
        }
    }  // namespace

    void addRunProperties(const RunRecord &record, ompl::tools::Benchmark::RunProperties &properties)
    {
        addWithPrefix(record, "", properties);
    }
}  // namespace ompl_core
