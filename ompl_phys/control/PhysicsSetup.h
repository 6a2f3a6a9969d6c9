/* Everything OMPL's control planners need for a physics scene, as a control::SimpleSetup: the
   state space (PhysicsStateSpace, with the robot-position projection registered as its default
   projection for KPIECE1, EST and PDST), a 2-D force control space bounded by the scene's maximum
   force, the ODE propagator with the manipulation knowledge, the validity checker, the start and a
   sampleable goal, the propagation step and control durations, and a grid decomposition for
   SyclopRRT and SyclopEST. Planners are picked by name with setPlannerByName(), or set directly.
   Not copyable: it owns the ODE world. */
#pragma once

#include "ompl_core/run/PlannerRegistry.h"
#include "ompl_phys/base/PhysicsStateSpace.h"
#include "ompl_phys/control/PhysicsStatePropagator.h"
#include "ompl_phys/control/RobotGridDecomposition.h"
#include "ompl_phys/knowledge/ManipulationKnowledge.h"
#include "ompl_phys/world/PhysicsWorld.h"

#include <ompl/control/SimpleSetup.h>

#include <memory>
#include <string>
#include <vector>

namespace ompl_phys
{
    class PhysicsSetup : public ompl::control::SimpleSetup
    {
    public:
        /** Shares scene (the world, space and knowledge keep it alive).
            @throws ompl_core::InputError naming the scene file and line when the start breaks a rule or
            overlaps something, or a fixed body covers the goal. */
        explicit PhysicsSetup(PhysicsScenePtr scene);
        /** Plans on a copy of scene. */
        explicit PhysicsSetup(const PhysicsScene &scene);
        PhysicsSetup(const PhysicsSetup &) = delete;
        PhysicsSetup &operator=(const PhysicsSetup &) = delete;

        const PhysicsScene &scene() const { return world_->scene(); }
        const PhysicsWorld &world() const { return *world_; }
        const ManipulationKnowledge &knowledge() const { return *knowledge_; }
        const PhysicsStateSpace &physicsSpace() const { return *space_; }
        const PhysicsStatePropagator &propagator() const { return *propagator_; }
        const std::shared_ptr<RobotGridDecomposition> &decomposition() const { return decomposition_; }
        const std::shared_ptr<PhysicsWorld> &worldPtr() const { return world_; }
        const std::shared_ptr<const ManipulationKnowledge> &knowledgePtr() const { return knowledge_; }

        /** The control planners that can plan on a PhysicsSetup: rrt, est, kpiece, sycloprrt,
            syclopest, pdst, sst. Add your own with add(). */
        static ompl_core::PlannerRegistry<PhysicsSetup> &plannerRegistry();

        /** Makes the registered planner called name, sets the scene's goal bias on it through its
            parameters when it declares "goal_bias", and makes it this setup's planner. An
            optimisation objective set by the previous planner is cleared first.
            @throws ompl_core::InputError for an unknown name. */
        void setPlannerByName(const std::string &name);

        /** Solved with an exact solution (solve() also reports approximate ones as solved). */
        bool haveExactSolution() const;

    private:
        explicit PhysicsSetup(std::shared_ptr<PhysicsWorld> world);
        static ompl::control::SpaceInformationPtr spaceInformation(const PhysicsWorld &world);
        void checkStart() const;

        std::shared_ptr<PhysicsWorld> world_;
        std::shared_ptr<const ManipulationKnowledge> knowledge_;
        std::shared_ptr<PhysicsStateSpace> space_;
        std::shared_ptr<PhysicsStatePropagator> propagator_;
        std::shared_ptr<RobotGridDecomposition> decomposition_;
    };
}  // namespace ompl_phys
