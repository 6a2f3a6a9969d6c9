#include "ompl_mm/primitives/PrimitiveTally.h"

namespace ompl_mm
{
    std::pair<std::string, std::uint64_t> PrimitiveTally::Record::mainReason() const
    {
        std::pair<std::string, std::uint64_t> main{"", 0};
        for (const auto &[reason, count] : reasons)
            if (count > main.second)
                main = {reason, count};
        return main;
    }

    PrimitiveTally::Record &PrimitiveTally::recordOf(PrimitiveKind kind)
    {
        const std::string_view name = primitiveKindName(kind);
        auto it = records_.find(name);
        if (it == records_.end())
            it = records_.emplace(std::string(name), Record()).first;
        return it->second;
    }

    void PrimitiveTally::attempt(PrimitiveKind kind, bool found, const std::string &reason)
    {
        Record &record = recordOf(kind);
        ++record.attempts;
        if (found)
            return;
        ++record.noMotion;
        ++record.reasons["found no motion: " +
                         (reason.empty() ? std::string("inverse kinematics found no solution") : reason)];
    }

    void PrimitiveTally::motion(PrimitiveKind kind, PrimitiveKind own, bool free, std::string_view bodyA,
                                std::string_view bodyB)
    {
        Record &record = recordOf(kind);
        ++record.motions;
        if (free)
        {
            ++recordOf(own).completed;
            return;
        }
        ++record.stopped;
        const std::string contact =
            bodyA.empty() || bodyB.empty()
                ? std::string("motion stopped without a contact (grazing)")
                : "motion stopped by " + std::string(bodyA) + " and " + std::string(bodyB);
        ++record.reasons[contact];
    }

    std::string PrimitiveTally::failureSummary() const
    {
        std::string summary;
        for (const auto &[kind, record] : records_)
        {
            if (!record.neverSucceeded())
                continue;
            const auto [reason, count] = record.mainReason();
            const std::uint64_t failures = record.noMotion + record.stopped;
            summary += kind + ": " + std::to_string(record.attempts) + " attempts, none succeeded";
            if (record.motions == 0 && record.noMotion < record.attempts)
                summary += "; no walk reached its motions (those before them were stopped)";
            else if (count > 0)
                summary +=
                    "; " + reason + " (" + std::to_string(count) + " of " + std::to_string(failures) + ")";
            summary += "\n";
        }
        return summary;
    }
}  // namespace ompl_mm
