/* A geometric::SimpleSetup for a manipulation scene: builds the robot model, the manipulation
   state space, the validity checker, the start state, the goal, the primitives and the MOPL
   planner with the scene's parameters, and checks the problem before any planning (robot start
   of the right size and inside the limits, objects resting, no collision at the start, a goal
   that can be reached). Use it like any SimpleSetup: solve(), getSolutionPath(), Benchmark. */
#pragma once

#include "ompl_mm/base/ManipulationGoal.h"
#include "ompl_mm/base/ManipulationValidityChecker.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/planners/MOPL.h"
#include "ompl_mm/primitives/PrimitiveFactory.h"

#include <ompl/geometric/SimpleSetup.h>

namespace ompl_mm
{
    class ManipulationSetup : public ompl::geometric::SimpleSetup
    {
    public:
        /** @param factory builds the scene's primitives; pass your own to add primitive types.
            @throws InputError naming the scene file and line of any fault in the problem. */
        explicit ManipulationSetup(const Scene &scene, const PrimitiveFactory &factory = PrimitiveFactory());

        const ManipulationModelPtr &model() const { return model_; }
        const ManipulationStateSpacePtr &manipulationSpace() const { return space_; }
        const std::shared_ptr<ManipulationValidityChecker> &validityChecker() const { return checker_; }
        const std::shared_ptr<ManipulationGoal> &manipulationGoal() const { return goal_; }
        /** The MOPL planner made for the scene (also set as the setup's planner). */
        const std::shared_ptr<MOPL> &mopl() const { return mopl_; }

        /** The solution as a ManipulationPath. @throws ompl::Exception when there is none. */
        ManipulationPath &manipulationPath() const;

    private:
        void setStartFromScene(const Scene &scene);
        void applyPlannerParameters(const Scene &scene);

        ManipulationModelPtr model_;
        ManipulationStateSpacePtr space_;
        std::shared_ptr<ManipulationValidityChecker> checker_;
        std::shared_ptr<ManipulationGoal> goal_;
        std::shared_ptr<MOPL> mopl_;
    };
}  // namespace ompl_mm
