/* One planning run of a manipulation scene as ompl_mm_plan makes it, for every program that wants
   the same run and the same record from a scene, a planner, a seed and a time limit. */
#pragma once

#include "ompl_core/run/ParameterSetting.h"
#include "ompl_core/run/RunRecord.h"
#include "ompl_core/run/SetupRun.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** What a planning run asks for (the defaults are ompl_mm_plan's). */
    struct PlanningRequest
    {
        std::string planner;                                  ///< a registered planner; empty: the scene's
        std::uint32_t seed{1};                                ///< OMPL's and MOPL's random seed
        double timeLimit{-1.0};                               ///< seconds; not positive: the scene's
        std::vector<ompl_core::ParameterSetting> parameters;  ///< planner parameters, after the scene's
        /** MOPL searches racing, one thread each (MoplRace); 1, the default, is one search in the
            calling thread. */
        unsigned int threads{1};
    };

    /** A planning run: seeds OMPL, builds the scene's ManipulationSetup (an impossible goal is thrown
        as the InputError at its scene line), selects the planner and applies the parameters; then
        solve() sets it up, reseeds OMPL as the benchmark tool does, solves within the time limit
        (every step polls it: MOPL's and the motion checks') and re-checks the solution once with
        OMPL's PathGeometric::check(). The same scene, request and seed give the same path and the
        same record. request() has the scene's planner when the request named none. With
        request.threads above 1, MOPL searches race (MoplRace), each on its own setup, seeded
        MoplRace::seedOf(seed, index); setup() is then the winner's, and the record's time is the
        race's. Not copyable: it owns its setups. */
    class PlanningRun : public ompl_core::SetupRun<ManipulationSetup, PlanningRequest>
    {
    public:
        /** Builds the run (the setup copies scene); loadSeconds is the time the caller spent loading the
           scene (the record's "load" phase); factory builds the scene's primitives. @throws
           ompl_core::InputError for a fault of the scene (its line), an unknown planner or a bad parameter
           (where the setting came from), or threads out of [1, MoplRace::MAX_SEARCHES] or above 1 for
           a planner other than MOPL. */
        PlanningRun(const Scene &scene, PlanningRequest request, double loadSeconds = 0.0,
                    const PrimitiveFactory &factory = PrimitiveFactory());

        /** Plans within the time limit or until stop becomes true, then re-checks the solution.
            @pre called once. */
        void solve(const ompl::base::PlannerTerminationCondition &stop);

        /** The time limit in seconds: the request's, else the scene's. */
        double timeLimit() const;
        /** Seconds solve() planned: the planner's planning time, or a race's wall time. */
        double planningTime() const;
        /** Whether solve() found an exact solution. */
        bool solved() const;
        /** OMPL's check() of the solution, made by solve(); nothing without a solution. */
        std::optional<bool> pathValid() const { return pathValid_; }

        /** The record ompl_mm_plan writes as JSON: manipulationRunResult() with the phases
            ("phases_s", the checks phase up to now). @pre solve() has been called. */
        ompl_core::RunResult record() const;

    private:
        /** Races setup_ and the rivals within termination; the winner becomes setup_. */
        void race(const ompl::base::PlannerTerminationCondition &termination);

        std::optional<bool> pathValid_;
        /** The other searches of a race (request.threads - 1); after solve() the winner is setup_. */
        std::vector<std::unique_ptr<ManipulationSetup>> rivals_;
        double raceSeconds_{0.0};  ///< wall time of a race's solve
    };
}  // namespace ompl_mm
