#pragma once

#include "ompl_core/io/InputError.h"
#include "ompl_core/run/ParameterSetting.h"
#include "ompl_core/run/PlannerRegistry.h"
#include "ompl_mm/base/ManipulationGoal.h"
#include "ompl_mm/base/ManipulationValidityChecker.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/geometric/ManipulationSimplifier.h"
#include "ompl_mm/planners/MOPL.h"
#include "ompl_mm/primitives/PrimitiveFactory.h"

#include <ompl/geometric/SimpleSetup.h>

#include <cstdint>
#include <optional>

namespace ompl_mm
{
    /** A geometric::SimpleSetup for a manipulation scene, the problem MOPL solves (see MOPL for
        the paper): builds the robot model, the manipulation state space, the validity checker, the
        start state, the goal, the primitives and the scene's planner (by name from the planner
        registry, with the scene's parameters), and checks the problem before any planning (robot
        start of the right size and inside the limits, objects resting, no collision at the start,
        a goal that can be reached: see goalFault()). Use it like any SimpleSetup: solve(), getSolutionPath(),
        Benchmark. The setup shares the model, space, checker, goal and primitives with the pieces
        that use them; they live as long as the last holder. */
    class ManipulationSetup : public ompl::geometric::SimpleSetup
    {
    public:
        /** Wires the scene (copied into the model, so it need not outlive the setup); factory
            builds the scene's primitives: pass your own to add primitive types.
            @throws ompl_core::InputError naming the scene file and line of any fault in the input
            (URDF, tool link, start, primitives), an unknown planner or a bad planner parameter. A
            goal that cannot be reached does not throw: see goalFault(). */
        explicit ManipulationSetup(const Scene &scene, const PrimitiveFactory &factory = PrimitiveFactory());

        /** Why the scene's goal cannot be reached from its start, found before planning (ProblemCheck:
            goal poses in collision or overlapping, an object that no primitive of the scene can
            move to its goal), with the scene line of the goal; nothing when no such fault was
            found. While the setup's goal is the problem's goal, solve() then returns at once
            ompl_core::infeasibleStatus() (INFEASIBLE in OMPL 1.6 and later, INVALID_GOAL in 1.5)
            and logs the fault. Programs that treat the scene as input throw it instead. */
        const std::optional<ompl_core::InputError> &goalFault() const { return goalFault_; }

        /** SimpleSetup::solve, or at once the status of goalFault() when there is one. */
        ompl::base::PlannerStatus solve(double time = 1.0) override;
        /** SimpleSetup::solve, or at once the status of goalFault() when there is one. */
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;

        /** The planners that can plan on a ManipulationSetup: "mopl", and OMPL's "rrtconnect",
            "rrt" and "est", which move the robot alone (their uniform samples keep the objects at
            their start poses; for tasks that need no manipulation). Add your own with add(). */
        static ompl_core::PlannerRegistry<ManipulationSetup> &plannerRegistry();

        /** Makes the registered planner called name and sets it as this setup's planner (without
            the scene's parameters: apply those with applyParameters() if wanted).
            @throws ompl_core::InputError for an unknown name. */
        void setPlannerByName(const std::string &name);

        /** Makes the registered planner called name, sets it as this setup's planner and gives it
            the scene's planner parameters that it declares (the scene writes them for its own
            planner type, so another planner takes those it knows and leaves the rest).
            @throws ompl_core::InputError for an unknown name or a bad value. */
        void selectPlanner(const std::string &name);

        /** Sets the planner's parameters (ompl_core::applyParameters), then checks MOPL's rules
            between parameters. @throws ompl_core::InputError naming a setting's place: of a bad
            setting, or of the last setting when the rules between them fail. */
        void applyParameters(const std::vector<ompl_core::ParameterSetting> &settings);
        /** Sets the parameters of planner, one of this setup's planners, as the member form does
            for the current planner. @throws as the member form. */
        static void applyParameters(ompl::base::Planner &planner,
                                    const std::vector<ompl_core::ParameterSetting> &settings);

        /** The problem: scene, robot and tool. */
        const ManipulationModelPtr &model() const { return model_; }
        /** The state space (also getStateSpace()). */
        const ManipulationStateSpacePtr &manipulationSpace() const { return space_; }
        /** The validity checker (also getStateValidityChecker()). */
        const std::shared_ptr<ManipulationValidityChecker> &validityChecker() const { return checker_; }
        /** The goal (also getGoal()). */
        const std::shared_ptr<ManipulationGoal> &manipulationGoal() const { return goal_; }
        /** The scene's primitives, as the factory built them. */
        const std::vector<PrimitivePtr> &primitives() const { return primitives_; }
        /** The current planner when it is MOPL, else null. */
        std::shared_ptr<MOPL> mopl() const;

        /** The solution as a ManipulationPath, owned by the problem definition (valid until its
            solutions are cleared). Another planner's PathGeometric takes its place as a
            ManipulationPath of the same states, labelled from their motions.
            @throws ompl::Exception when there is none. */
        ManipulationPath &manipulationPath() const;
        /** Mode-aware smoothing of the solution in place (ManipulationSimplifier, as MOPL applies it
            to its solutions): pointless pushes removed, `attempts` random windows replanned,
            drawing from an RNG seeded with seed. Unlike SimpleSetup::simplifySolution it can drop
            manipulation. @throws ompl::Exception when there is no solution. */
        ManipulationSimplifier::Outcome smoothSolution(unsigned int attempts = 30,
                                                       std::uint_fast32_t seed = 1);

    private:
        void setStartFromScene(const Scene &scene);

        ManipulationModelPtr model_;
        ManipulationStateSpacePtr space_;
        std::shared_ptr<ManipulationValidityChecker> checker_;
        std::shared_ptr<ManipulationGoal> goal_;
        std::vector<PrimitivePtr> primitives_;
        std::optional<ompl_core::InputError> goalFault_;
    };
}  // namespace ompl_mm
