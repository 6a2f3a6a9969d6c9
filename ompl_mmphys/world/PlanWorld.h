/* The ODE world of a manipulation scene, in which a plan is executed: the robot's links driven like
   a position-controlled robot, the objects free rigid bodies with mass and friction. */
#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <Eigen/Geometry>

#include <memory>
#include <vector>

struct dxBody;  // ODE's body, whose handle is a pointer to it

namespace ompl_mmphys
{
    /** How far above or below a support surface a simulated object's base may be and still rest
        on it, metres: contacts sink a little, and objects settle. */
    constexpr double REST_SNAP = 0.01;

    /** The index of the surface of scene on which a simulated object whose base centre is at base
        rests (within REST_SNAP of its height, inside its bounds), or -1. */
    int surfaceUnder(const ompl_mm::Scene &scene, const Eigen::Vector3d &base);

    /** What the world needs beyond the scene. The scene gives each object's mass and friction;
        everything else rubs with the friction here. */
    struct WorldSettings
    {
        double gravity{-9.81};             ///< along world z, m/s²
        double robotFriction{0.5};         ///< friction coefficient of the robot's links
        double obstacleFriction{0.5};      ///< of obstacles and support surfaces
        unsigned int iterations{50};       ///< ODE QuickStep iterations per step
        unsigned int maxContactPoints{8};  ///< per touching pair of geoms
    };

    /** An ODE world built from a manipulation scene: every robot link with collision shapes a
        kinematic body (moved by the caller, pushing what it meets without being pushed back), every
        movable object a dynamic body (its shape, mass and friction from the scene), obstacles
        static geometry, and each support surface that is no obstacle's top a static slab whose top
        is the surface. An object that falls a metre below the lowest surface or obstacle stops
        there (it fell out of the world). Contact friction between two bodies is the geometric mean of theirs.
       An object can be held: it then moves rigidly with the tool (a rigid grasp) until released. Not copyable
       (it owns ODE handles); not thread-safe (one world per thread). */
    class PlanWorld
    {
    public:
        /** Builds the world of model's scene with the robot at joint values robot (size dof) and
            the objects at poses (one per object of the scene), at rest; when `present` is not
            empty, only the objects it marks true are in the world (a smaller world is quicker;
            asking for an absent object's pose throws).
            @throws ompl::Exception when poses (or a non-empty present) does not hold one entry per
            object. */
        PlanWorld(ompl_mm::ManipulationModelPtr model, const double *robot,
                  const std::vector<ompl_mm::ObjectPose> &poses, const WorldSettings &settings = {},
                  const std::vector<bool> &present = {});
        /** Frees the ODE world, its bodies and geometry. */
        ~PlanWorld();
        PlanWorld(const PlanWorld &) = delete;             ///< not copyable: it owns ODE handles
        PlanWorld &operator=(const PlanWorld &) = delete;  ///< not copyable: it owns ODE handles

        /** The scene, robot and tool. */
        const ompl_mm::ManipulationModel &model() const { return *model_; }

        /** Puts the robot at joint values from and gives its links the velocities that take them to
            joint values to in dt seconds, which the next step() carries out; held objects follow
            the tool. @pre dt > 0. */
        void driveRobot(const double *from, const double *to, double dt);

        /** Holds object: from now on it moves rigidly with the tool, keeping its present pose
            relative to the tool, and is moved by nothing else. */
        void hold(unsigned int object);
        /** Lets a held object go, at rest. */
        void release(unsigned int object);
        /** Whether object is held. */
        bool isHeld(unsigned int object) const;

        /** Makes object the only free object until thaw(): the others stay still (ODE leaves them
            out of its solver) unless something touches them, and ODE's random order of
            constraints starts afresh, so that a push computes alike whichever other objects
            the world holds. */
        void isolate(unsigned int object);
        /** Frees every object that isolate() held still. */
        void thaw();

        /** Advances the world by dt seconds. */
        void step(double dt);

        /** The object's pose: its base centre (the frame's origin moved down half its height along
            the object's own z axis) and its yaw. */
        ompl_mm::ObjectPose objectPose(unsigned int object) const;
        /** The angle between the object's z axis and the world's, radians: 0 upright. */
        double objectTilt(unsigned int object) const;
        /** The object's linear speed, m/s. */
        double objectSpeed(unsigned int object) const;
        /** True when every free object (neither held nor held still by isolate()) moves slower
            than speed (m/s) and turns slower than spin (rad/s). */
        bool atRest(double speed, double spin) const;
        /** The sum of the forces the robot's links exerted on the objects in the last step, N (world
            frame; objects held excluded). */
        Eigen::Vector3d robotContactForce() const;

    private:
        struct Handles;
        /** The body of a present object. @throws ompl::Exception for an absent one. */
        dxBody *objectBody(unsigned int object) const;
        void collide();
        void handlePair(void *geomA, void *geomB);
        void placeHeld(const Eigen::Isometry3d &tool, const Eigen::Isometry3d &nextTool, double dt);

        ompl_mm::ManipulationModelPtr model_;
        WorldSettings settings_;
        std::unique_ptr<Handles> handles_;
    };
}  // namespace ompl_mmphys
