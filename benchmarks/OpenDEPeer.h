/* The peer that bench_opende_peer measures ompl_phys against: OMPL 1.5's own ODE extension
   (ompl/extensions/ode) set up on a physics scene the way its demo OpenDERigidBodyPlanning.cpp sets
   up a world. It is built from the same PhysicsScene as ours, with the same physical parameters
   (gravity, ERP, CFM, surface layer, contacts per pair, friction, QuickStep iterations, ODE step)
   and the same control durations in seconds; peerDifferences() lists where it differs from ours and
   why. */
#pragma once

#include "ompl_phys/scene/PhysicsScene.h"
#include "ompl_phys/world/BodyState.h"
#include "ompl_phys/world/OdeGeometry.h"

#include <ompl/control/planners/syclop/GridDecomposition.h>
#include <ompl/extensions/ode/OpenDESimpleSetup.h>

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace opende_peer
{
    /** How the peer differs from ours, mostly for what the extension cannot express, a sentence or
        two each, for the benchmark's printed notes. */
    const std::vector<std::string> &peerDifferences();

    /** The scene's ODE world as an OpenDEEnvironment: the floor (the plane z = 0) and the fixed
        bodies as static geoms in one hash space (as the demo), the robot sphere and the free and
        constraint-oriented bodies as dynamic bodies with the scene's masses. The state bodies are
        the robot, then the movable bodies in scene order (ours' numbering, BodyState). A control is
        a horizontal force on the robot, bounded by the scene's maximum force. Every contact is
        allowed except the robot's with a fixed body; contacts are soft (the scene's ERP and CFM)
        with the scene's friction: robot_floor between the robot and the floor, default for the
        rest. The extension takes one ODE step per propagation step, so stepSize_ is the scene's
        step divided by its substeps, and the control durations count those steps.
        Not copyable: it owns ODE handles. Not thread-safe, as the extension's propagator. */
    class PeerEnvironment : public ompl::control::OpenDEEnvironment
    {
    public:
        /** Builds the world for scene, which it shares, with every body at its start, at rest.
            @pre ODE is initialised (dInitODE2) and scene is not null. */
        explicit PeerEnvironment(ompl_phys::PhysicsScenePtr scene);
        /** Frees the ODE world, its space and geoms. */
        ~PeerEnvironment() override;
        /** Not copyable: it owns ODE handles. */
        PeerEnvironment(const PeerEnvironment &) = delete;
        /** Not copyable: it owns ODE handles. */
        PeerEnvironment &operator=(const PeerEnvironment &) = delete;

        /** The extension's hook: a force along world x and y, N. */
        unsigned int getControlDimension() const override { return 2; }
        /** The extension's hook: each component within the scene's maximum force. */
        void getControlBounds(std::vector<double> &lower, std::vector<double> &upper) const override;
        /** The extension's hook: the force on the robot's centre for the next ODE step. */
        void applyControl(const double *control) const override;
        /** The extension's hook: false only for the robot touching a fixed body. */
        bool isValidCollision(dGeomID geom1, dGeomID geom2, const dContact &contact) const override;
        /** The extension's hook: no contacts between two static geoms (neither moves), maxContacts_
            otherwise. */
        unsigned int getMaxContacts(dGeomID geom1, dGeomID geom2) const override;
        /** The extension's hook: the scene's soft contact with its friction for the pair. */
        void setupContact(dGeomID geom1, dGeomID geom2, dContact &contact) const override;

        /** The scene the world was built from. */
        const ompl_phys::PhysicsScene &scene() const { return *scene_; }

        /** Puts every state body in its state: states holds the robot first, then the movable
            bodies in scene order, as stateBodies_. */
        void placeBodies(const ompl_phys::BodyStates &states) const;

        /** The floor plane. */
        dGeomID floorGeom() const { return floor_; }
        /** The robot sphere. */
        dGeomID robotGeom() const { return robot_; }
        /** The fixed bodies' geoms, in scene order. */
        const std::vector<dGeomID> &fixedGeoms() const { return fixed_; }
        /** The movable bodies' geoms, in the order of stateBodies_ after the robot. */
        const std::vector<dGeomID> &movableGeoms() const { return movable_; }

    private:
        ompl_phys::PhysicsScenePtr scene_;
        dSpaceID space_{nullptr};
        dGeomID floor_{nullptr};
        dGeomID robot_{nullptr};
        std::vector<dGeomID> fixed_;
        std::vector<dGeomID> movable_;
        std::deque<ompl_phys::ConvexPrismData> prisms_;  // ODE keeps pointers into them
    };

    /** Everything OMPL's control planners need for the peer, as the extension's OpenDESimpleSetup
        with what the demo adds: an OpenDEStateSpace whose distance is the robot's (the demo's
        measures its body's) and whose default projection is the robot's position on the floor
        (cells as ours, for KPIECE1), a goal (the robot's centre in the scene's goal disc, sampleable
        as SyclopRRT needs), the OpenDEStateValidityChecker, and a grid over the robot's region for
        SyclopRRT (as ours). The state space's bounds are the
        scene's limits per body: positions within the robot's or the bodies' region, velocities
        within the speed limits. The start is the environment's initial state.
        Not copyable: it owns the environment. */
    class PeerSetup : public ompl::control::OpenDESimpleSetup
    {
    public:
        /** The planners setPlannerByName() knows. */
        static const std::vector<std::string> &plannerNames();

        /** A fresh world and setup for scene, which it shares.
            @pre ODE is initialised (dInitODE2) and scene is not null. */
        explicit PeerSetup(ompl_phys::PhysicsScenePtr scene);
        /** Not copyable: it owns the environment. */
        PeerSetup(const PeerSetup &) = delete;
        /** Not copyable: it owns the environment. */
        PeerSetup &operator=(const PeerSetup &) = delete;

        /** The world the propagator simulates in. */
        const PeerEnvironment &environment() const { return *environment_; }

        /** Makes the planner called name (one of plannerNames()) this setup's planner, with the
            scene's goal bias when it declares one, as ours.
            @throws ompl_core::InputError for an unknown name. */
        void setPlannerByName(const std::string &name);

        /** The bodies of a state of this setup's space, robot first. */
        ompl_phys::BodyStates bodyStates(const ompl::base::State *state) const;

    private:
        explicit PeerSetup(std::shared_ptr<PeerEnvironment> environment);

        std::shared_ptr<PeerEnvironment> environment_;
        std::shared_ptr<ompl::control::GridDecomposition> decomposition_;
    };
}  // namespace opende_peer
