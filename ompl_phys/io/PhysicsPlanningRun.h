/* One planning run of a physics scene as ompl_phys_plan makes it, for every program that wants the
   same run and the same record from a scene, a planner, a seed and a time limit. */
#pragma once

#include "ompl_core/run/ParameterSetting.h"
#include "ompl_core/run/RunRecord.h"
#include "ompl_core/run/SetupRun.h"
#include "ompl_phys/control/PathSimulation.h"
#include "ompl_phys/control/PhysicsSetup.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_phys
{
    /** What a physics planning run asks for (the defaults are ompl_phys_plan's). */
    struct PhysicsPlanningRequest
    {
        std::string planner{"kpiece"};                        ///< a registered control planner
        std::uint32_t seed{1};                                ///< OMPL's random seed
        double timeLimit{-1.0};                               ///< seconds; not positive: the scene's
        std::vector<ompl_core::ParameterSetting> parameters;  ///< planner parameters
    };

    /** A physics planning run: seeds OMPL, builds the scene's PhysicsSetup (an impossible goal is
        thrown as the InputError at its scene line), selects the planner and applies the
        parameters; then solve() sets it up, reseeds OMPL as the benchmark tool does, solves within
        the time limit and re-simulates an exact solution's controls in a fresh world
        (simulatePath). The same scene, request and seed give the same path and the same record.
        Not copyable: it owns its setup (and its ODE world). */
    class PhysicsPlanningRun : public ompl_core::SetupRun<PhysicsSetup, PhysicsPlanningRequest>
    {
    public:
        /** Builds the run (the setup copies scene); loadSeconds is the time the caller spent
            loading the scene (the record's "load" phase). @throws ompl_core::InputError for a
            fault of the scene (its line), an unknown planner or a bad parameter. */
        PhysicsPlanningRun(const PhysicsScene &scene, PhysicsPlanningRequest request,
                           double loadSeconds = 0.0);

        /** Plans within the time limit or until stop becomes true, then re-simulates the solution.
            @pre called once. */
        void solve(const ompl::base::PlannerTerminationCondition &stop);

        /** The time limit in seconds: the request's, else the scene's. */
        double timeLimit() const;
        /** Whether solve() found an exact solution. */
        bool solved() const { return setup_->haveExactSolution(); }
        /** The re-simulation of the solution, made by solve(); null without a solution. */
        const SimulatedPath *simulated() const { return simulated_ ? &*simulated_ : nullptr; }

        /** The record ompl_phys_plan writes as JSON: physicsRunResult() with the phases
            ("phases_s", the checks phase up to now). @pre solve() has been called. */
        ompl_core::RunResult record() const;

    private:
        std::optional<SimulatedPath> simulated_;
    };
}  // namespace ompl_phys
