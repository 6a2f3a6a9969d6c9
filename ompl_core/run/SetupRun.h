/* What the planning runs of both libraries share (ompl_mm::PlanningRun, ompl_phys::PhysicsPlanningRun):
   the request, the setup they own and where their wall time went. */
#pragma once

#include "ompl_core/run/PhaseTimes.h"
#include "ompl_core/run/RunRecord.h"

#include <memory>
#include <string>
#include <utility>
#include <variant>

namespace ompl_core
{
    /** A planning run's request, its Setup (a SimpleSetup of one library) and its phases. Not
        copyable: it owns its setup. */
    template <typename Setup, typename Request>
    class SetupRun
    {
    public:
        SetupRun(const SetupRun &) = delete;
        SetupRun &operator=(const SetupRun &) = delete;

        /** The setup, its planner chosen and parameters applied. */
        Setup &setup() { return *setup_; }
        /** The setup, read-only. */
        const Setup &setup() const { return *setup_; }
        /** The request, as the run completed it. */
        const Request &request() const { return request_; }
        /** Where the run's wall time went; its "checks" phase runs until the caller ends it. */
        PhaseTimes &phases() { return phases_; }
        /** Adds a record of the caller's (what a layer above learnt of the run, such as a physics
            check of its path) to the run's record, under key, before the phases.
            @throws ompl::Exception when key is empty, holds a '.' or was added before. */
        void addRecord(const std::string &key, const RunRecord &record) { added_.addRecord(key, record); }

    protected:
        /** loadSeconds: the time the caller spent loading the scene (the "load" phase). */
        SetupRun(Request request, double loadSeconds) : request_(std::move(request))
        {
            phases_.load = loadSeconds;
        }
        ~SetupRun() = default;

        /** result with the callers' records and then the phases added ("phases_s", the checks
            phase up to now). */
        RunResult withPhases(RunResult result) const
        {
            for (const RunRecord::Entry &entry : added_.entries())
                result.details.addRecord(entry.key, std::get<RunRecord>(entry.value));
            PhaseTimes phases = phases_;
            phases.checks = phases.sinceLap();
            result.details.addRecord("phases_s", phases.record());
            return result;
        }

        RunRecord added_;               ///< the callers' records, by key
        Request request_;               ///< what the run was asked, as the run completed it
        PhaseTimes phases_;             ///< where its wall time went
        std::unique_ptr<Setup> setup_;  ///< made by the derived run's constructor
    };
}  // namespace ompl_core
