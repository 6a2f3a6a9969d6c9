// Test helpers shared by the planning-run tests of both libraries: stops that never or always hold,
// and two run records compared without their times, which differ between any two runs.
#pragma once

#include "ompl_core/run/RunRecord.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <variant>

namespace ompl_core::test
{
    /** A stop that never holds: the run ends at its time limit or when solved. */
    inline const ompl::base::PlannerTerminationCondition NEVER_STOP([] { return false; });
    /** A stop that holds from the start. */
    inline const ompl::base::PlannerTerminationCondition STOP_AT_ONCE([] { return true; });

    /** A Request (ompl_mm::PlanningRequest, ompl_phys::PhysicsPlanningRequest) with its defaults but
        seed and time limit (seconds; not positive: the scene's). */
    template <typename Request>
    Request seededRequest(std::uint32_t seed, double timeLimit = -1.0)
    {
        Request request;
        request.seed = seed;
        request.timeLimit = timeLimit;
        return request;
    }

    /** "" when a and b hold the same keys in the same order with the same values, keys that start
        with "time" and the "phases_s" record aside; else the first difference's dotted key. */
    inline std::string firstDifferenceBesidesTimes(const RunRecord &a, const RunRecord &b,
                                                   const std::string &prefix = "")
    {
        if (a.entries().size() != b.entries().size())
            return prefix + "(entry count)";
        for (std::size_t i = 0; i < a.entries().size(); ++i)
        {
            const RunRecord::Entry &x = a.entries()[i];
            const RunRecord::Entry &y = b.entries()[i];
            if (x.key != y.key)
                return prefix + x.key + " / " + y.key;
            if (x.key.rfind("time", 0) == 0 || x.key == "phases_s")
                continue;
            if (x.value.index() != y.value.index())
                return prefix + x.key;
            const std::string difference = std::visit(
                [&](const auto &value) -> std::string
                {
                    using Value = std::decay_t<decltype(value)>;
                    if constexpr (std::is_same_v<Value, RunRecord>)
                        return firstDifferenceBesidesTimes(value, std::get<RunRecord>(y.value),
                                                           prefix + x.key + ".");
                    else
                        return value == std::get<Value>(y.value) ? "" : prefix + x.key;
                },
                x.value);
            if (!difference.empty())
                return difference;
        }
        return "";
    }
}  // namespace ompl_core::test
