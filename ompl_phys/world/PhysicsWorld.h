/* An ODE world built from a PhysicsScene: the robot sphere and the movable bodies as dynamic
   bodies, fixed bodies and the floor as static geometry, the scene's materials and contact
   parameters. It steps the simulation with a horizontal force on the robot and records which
   scene bodies the robot touched during the step, for the manipulation knowledge to judge.
   Not copyable (it owns ODE handles); not thread-safe (one world per thread). */
#pragma once

#include "ompl_phys/scene/PhysicsScene.h"
#include "ompl_phys/world/BodyState.h"

#include <memory>
#include <vector>

namespace ompl_phys
{
    class PhysicsWorld
    {
    public:
        /** @throws ompl::Exception for shapes ODE cannot simulate (a movable prism). */
        explicit PhysicsWorld(PhysicsScenePtr scene);
        ~PhysicsWorld();
        PhysicsWorld(const PhysicsWorld &) = delete;
        PhysicsWorld &operator=(const PhysicsWorld &) = delete;

        const PhysicsScene &scene() const { return *scene_; }
        const PhysicsScenePtr &scenePtr() const { return scene_; }

        /** Robot plus movable bodies. */
        std::size_t movingBodyCount() const { return 1 + movable_.size(); }

        /** Scene body index of moving body i >= 1. */
        std::size_t sceneBodyOf(std::size_t movingIndex) const { return movable_.at(movingIndex - 1); }

        /** Name of moving body i (the robot's name for 0). */
        const std::string &movingBodyName(std::size_t movingIndex) const;

        /** The state of every moving body at the scene's start, at rest. */
        BodyStates startStates() const;

        void setStates(const BodyStates &states);
        void readStates(BodyStates &states) const;

        /** Advances the world by dt seconds with a horizontal force (N) on the robot's centre. */
        void step(const Eigen::Vector2d &force, double dt);

        /** Runs collision detection at the current state without moving anything; touches() then
            lists the bodies the robot touches. Returns the deepest penetration among all pairs
            that involve a moving body, metres. */
        double detectContacts();

        /** Scene body indices the robot touched in the last step() or detectContacts(), ascending,
            without repeats. */
        const std::vector<std::size_t> &touches() const { return touches_; }

        /** Resets ODE's global random generator, which QuickStep draws from when contacts exist,
            so a simulation from the same state and force gives bit-identical results. */
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
