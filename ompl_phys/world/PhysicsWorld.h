#pragma once

#include "ompl_phys/scene/PhysicsScene.h"
#include "ompl_phys/world/BodyState.h"

#include <memory>
#include <vector>

namespace ompl_phys
{
    /** An ODE world built from a PhysicsScene: the robot sphere and the movable bodies as dynamic
        bodies, fixed bodies and the floor (the plane z = 0) as static geometry, the scene's
        materials and contact parameters. It steps the simulation with a horizontal force on the
        robot and records which scene bodies the robot touched during the step, for the
        manipulation knowledge to judge. Moving bodies are numbered as in BodyState: the robot (0),
        then the movable bodies in scene order.
        Not copyable (it owns ODE handles); not thread-safe (one world per thread). */
    class PhysicsWorld
    {
    public:
        /** Builds the world for scene, which it shares, and puts every body at its start, at rest.
            @pre scene is not null.
            @throws ompl::Exception for shapes ODE cannot simulate (a movable prism). */
        explicit PhysicsWorld(PhysicsScenePtr scene);
        /** Frees the ODE world, its bodies, geometry and contacts. */
        ~PhysicsWorld();
        /** Not copyable: it owns ODE handles. */
        PhysicsWorld(const PhysicsWorld &) = delete;
        /** Not copyable: it owns ODE handles. */
        PhysicsWorld &operator=(const PhysicsWorld &) = delete;

        /** The scene the world was built from. */
        const PhysicsScene &scene() const { return *scene_; }
        /** The shared scene, for objects that must keep it alive. */
        const PhysicsScenePtr &scenePtr() const { return scene_; }

        /** Robot plus movable bodies. */
        std::size_t movingBodyCount() const { return 1 + movable_.size(); }

        /** Scene body index of moving body movingIndex.
            @throws std::out_of_range unless 1 <= movingIndex < movingBodyCount(). */
        std::size_t sceneBodyOf(std::size_t movingIndex) const { return movable_.at(movingIndex - 1); }

        /** Name of moving body movingIndex (the robot's name for 0).
            @throws std::out_of_range when movingIndex >= movingBodyCount(). */
        const std::string &movingBodyName(std::size_t movingIndex) const;

        /** The state of every moving body at the scene's start, at rest. */
        BodyStates startStates() const;

        /** Puts every moving body in its state and clears the forces and torques accumulated on
            them. @pre states holds at least movingBodyCount() entries, robot first. */
        void setStates(const BodyStates &states);
        /** The current state of every moving body; states is resized to movingBodyCount(). */
        void readStates(BodyStates &states) const;

        /** Advances the world by dt seconds with a horizontal force (N, world x and y) on the robot's
            centre, applied for this step only. The robot's touches are found by the collision
            check at the start of the step, before the bodies move. */
        void step(const Eigen::Vector2d &force, double dt);

        /** Runs collision detection at the current state without moving anything; touches() then
            lists the bodies the robot touches. Returns the deepest penetration among all pairs
            that involve a moving body, metres. */
        double detectContacts();

        /** The deepest penetration between two geoms, one of them moving, that the collision check
            of the last step() (at its start) or detectContacts() found, metres. */
        double deepestPenetration() const { return deepest_; }

        /** Scene body indices the robot touched in the last step() or detectContacts(), ascending,
            without repeats. Valid until the next step() or detectContacts(). */
        const std::vector<std::size_t> &touches() const { return touches_; }

        /** Resets ODE's global random generator, which QuickStep draws from when contacts exist,
            so a simulation from the same state and force gives bit-identical results. The
            generator is shared by every world in the process. */
        static void resetRandomSeed();

    private:
        struct Handles;
        void collide();
        void handlePair(void *geomA, void *geomB);

        PhysicsScenePtr scene_;
        std::vector<std::size_t> movable_;
        std::unique_ptr<Handles> handles_;
        std::vector<std::size_t> touches_;
        double deepest_{0.0};
        bool createContacts_{true};
    };
}  // namespace ompl_phys
