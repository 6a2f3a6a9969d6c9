#pragma once

#include "ompl_core/io/InputError.h"
#include "ompl_core/run/PlannerRegistry.h"
#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/control/PhysicsStatePropagator.h"
#include "ompl_phys/control/RobotGridDecomposition.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"
#include "ompl_phys/world/PhysicsWorld.h"

#include <ompl/control/SimpleSetup.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_phys
{
    /** Everything OMPL's control planners need for a physics scene, as a control::SimpleSetup: the
        state space (PhysicsStateSpace, with the robot-position projection registered as its default
        projection for KPIECE1, EST and PDST), a 2-D force control space bounded by the scene's
        maximum force, the ODE propagator with the manipulation knowledge, the validity checker, the
        start and a sampleable goal, the propagation step and control durations, and a grid
        decomposition for SyclopRRT and SyclopEST. Planners are picked by name with
        setPlannerByName(), or set directly; a new setup starts with kpiece.
        Not copyable: it owns the ODE world (shared with its propagator). Not thread-safe: the
        propagator simulates in that one world, so plan and re-simulate from one thread at a time.

        @par External documentation
        Muhayyuddin, A. Akbari, J. Rosell, "Physics-based Motion Planning: Evaluation Criteria and
        Benchmarking", ROBOT 2015: Second Iberian Robotics Conference, Advances in Intelligent
        Systems and Computing vol. 417, Springer, 2016, pp. 43–55, DOI 10.1007/978-3-319-27146-0_4. */
    class PhysicsSetup : public ompl::control::SimpleSetup
    {
    public:
        /** Shares scene (the world, space and knowledge keep it alive).
            @pre scene is not null.
            @throws ompl_core::InputError naming the scene file and line when the start breaks a rule or
            overlaps something (a goal that cannot be reached does not throw: see goalFault()).
            @throws ompl::Exception for a movable prism, which ODE cannot simulate. */
        explicit PhysicsSetup(PhysicsScenePtr scene);
        /** Plans on a copy of scene; throws as the shared form. */
        explicit PhysicsSetup(const PhysicsScene &scene);
        /** Not copyable: it owns the ODE world. */
        PhysicsSetup(const PhysicsSetup &) = delete;
        /** Not copyable: it owns the ODE world. */
        PhysicsSetup &operator=(const PhysicsSetup &) = delete;

        /** The scene planned on. */
        const PhysicsScene &scene() const { return world_->scene(); }
        /** The ODE world the propagator simulates in. */
        const PhysicsWorld &world() const { return *world_; }
        /** The rules the propagator, the validity checker and the goal judge by. */
        const ManipulationKnowledge &knowledge() const { return *knowledge_; }
        /** The state space, as its own type. */
        const PhysicsStateSpace &physicsSpace() const { return *space_; }
        /** The propagator, for its counters. */
        const PhysicsStatePropagator &propagator() const { return *propagator_; }
        /** The robot grid that the SyCLoP planners are built with. */
        const std::shared_ptr<RobotGridDecomposition> &decomposition() const { return decomposition_; }
        /** The world, shared, for code that simulates in it (the propagator writes its state
            afresh on every call). */
        const std::shared_ptr<PhysicsWorld> &worldPtr() const { return world_; }
        /** The knowledge, shared, for objects that must keep it alive. */
        const std::shared_ptr<const ManipulationKnowledge> &knowledgePtr() const { return knowledge_; }

        /** The control planners that can plan on a PhysicsSetup: rrt, est, kpiece, sycloprrt,
            syclopest, pdst, sst. Add your own with add(). One registry per process. */
        static ompl_core::PlannerRegistry<PhysicsSetup> &plannerRegistry();

        /** Makes the registered planner called name, sets the scene's goal bias on it through its
            parameters when it declares "goal_bias", and makes it this setup's planner. An
            optimisation objective set by the previous planner is cleared first.
            @throws ompl_core::InputError for an unknown name, or a goal bias the planner rejects. */
        void setPlannerByName(const std::string &name);

        /** Why the scene's goal cannot be reached, found before planning (a fixed body covers its
            centre), with the scene line of the goal; nothing when no such fault was found. While the
            setup's goal is the problem's goal, solve() then returns at once
            ompl_core::infeasibleStatus() (INFEASIBLE in OMPL 1.6 and later, INVALID_GOAL in 1.5)
            and logs the fault. Programs that treat the scene as input throw it instead. */
        const std::optional<ompl_core::InputError> &goalFault() const { return goalFault_; }

        /** SimpleSetup::solve, or at once the status of goalFault() when there is one. */
        ompl::base::PlannerStatus solve(double time = 1.0) override;
        /** SimpleSetup::solve, or at once the status of goalFault() when there is one. */
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;

        /** Solved with an exact solution (solve() also reports approximate ones as solved). */
        bool haveExactSolution() const;

    private:
        explicit PhysicsSetup(std::shared_ptr<PhysicsWorld> world);
        static ompl::control::SpaceInformationPtr spaceInformation(const PhysicsWorld &world);
        void checkStart() const;
        /** The fault of the scene's goal, as goalFault() gives it. */
        std::optional<ompl_core::InputError> findGoalFault() const;

        std::shared_ptr<PhysicsWorld> world_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
        std::shared_ptr<PhysicsStateSpace> space_;
        std::shared_ptr<PhysicsStatePropagator> propagator_;
        std::shared_ptr<RobotGridDecomposition> decomposition_;
        std::shared_ptr<ompl::base::Goal> goal_;
        std::optional<ompl_core::InputError> goalFault_;
    };
}  // namespace ompl_phys
