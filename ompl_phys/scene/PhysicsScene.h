#pragma once

#include "ompl_core/io/SourceLocation.h"

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace ompl_phys
{
    /** What the manipulation knowledge says about a body. */
    enum class BodyKind
    {
        Fixed,       ///< never moves; the robot must not touch it
        Free,        ///< may be pushed from anywhere, in any direction
        Constrained  ///< may be pushed only from its push region and only along its push axis
    };

    /** A collision shape: URDF's box, cylinder (along z) and sphere, plus an upright triangular prism.
        Centred at the body frame's origin; lengths in metres. */
    struct PhysicsShape
    {
        /** Which of the shapes, and so which fields are used. */
        enum class Kind
        {
            Box,       ///< boxSize
            Cylinder,  ///< radius and length, axis along the body's z
            Sphere,    ///< radius
            Prism      ///< triangle extruded by length along z; only for fixed bodies
        };
        Kind kind{Kind::Box};                              ///< the shape; its fields are listed at Kind
        Eigen::Vector3d boxSize{Eigen::Vector3d::Zero()};  ///< box edge lengths
        double radius{0.0};                                ///< cylinder or sphere radius
        double length{0.0};                                ///< cylinder or prism length along z
        Eigen::Matrix<double, 2, 3> triangle;              ///< prism corners (columns), x y in the body frame

        /** Half of the extent along z: how high the centre sits above a floor it rests on, metres. */
        double halfHeight() const;

        /** Radius of the smallest vertical cylinder about the body's z axis that contains the shape,
            metres. */
        double boundingRadius() const;
    };

    /** Where and along which axis a constraint-oriented body may be pushed. */
    struct PushConstraint
    {
        Eigen::Vector3d axis{Eigen::Vector3d::UnitX()};  ///< unit push axis in the body frame
        double stripHalfWidth{
            0.0};  ///< the robot centre may touch the body only within this distance of the axis line, m
        double lateralTolerance{0.0};  ///< allowed distance of the body centre from its start axis line, m
        double angleTolerance{0.0};    ///< allowed rotation away from the start orientation, radians
    };

    /** A rigid body of the scene (not the robot). */
    struct PhysicsBody
    {
        std::string name;                                        ///< unique within the scene
        BodyKind kind{BodyKind::Free};                           ///< what the knowledge allows with it
        PhysicsShape shape;                                      ///< collision shape in the body frame
        Eigen::Isometry3d start{Eigen::Isometry3d::Identity()};  ///< pose at the start, body frame to world
        double mass{0.0};                                        ///< kg; unused for fixed bodies
        PushConstraint push;                                     ///< only for constrained bodies
        ompl_core::SourceLocation where;                         ///< its scene file element, for messages
    };

    /** The robot: a sphere on the floor, driven by a horizontal force. */
    struct PhysicsRobot
    {
        std::string name{"robot"};                       ///< names the robot in results and pictures
        double radius{0.0};                              ///< m
        double mass{0.0};                                ///< kg
        Eigen::Vector3d start{Eigen::Vector3d::Zero()};  ///< centre at the start, world frame, m
        ompl_core::SourceLocation where;                 ///< its scene file element, for messages
    };

    /** Coulomb friction coefficients between classes of bodies (the material model). */
    struct Materials
    {
        double robotFloor{0.0};           ///< the robot slides on the floor
        double defaultMu{0.7};            ///< every other pair
        ompl_core::SourceLocation where;  ///< its scene file element, for messages
    };

    /** How ODE integrates and handles contacts. */
    struct ContactParameters
    {
        double erp{0.5};                  ///< contact error reduction parameter, in (0, 1]
        double cfm{1e-4};                 ///< contact constraint force mixing, >= 0
        unsigned int maxContacts{3};      ///< contact points per touching pair
        unsigned int iterations{20};      ///< QuickStep iterations
        unsigned int substeps{7};         ///< ODE steps per propagation step
        double gravity{-9.81};            ///< along z, m/s^2
        ompl_core::SourceLocation where;  ///< its scene file element, for messages
    };

    /** Limits of the planning problem. */
    struct PlanningLimits
    {
        Eigen::AlignedBox2d robotRegion;   ///< where the robot centre may be (world x, y, m)
        Eigen::AlignedBox2d bodyRegion;    ///< where movable body centres may be (world x, y, m)
        double maxRobotSpeed{1.0};         ///< m/s, the robot's horizontal speed (norm of its velocity)
        double maxBodySpeed{5.0};          ///< m/s, a movable body's speed (norm of its linear velocity)
        double maxAngularSpeed{100.0};     ///< rad/s, norm of any angular velocity (divergence guard)
        double maxForce{10.0};             ///< N, each control component
        double stepSize{0.07};             ///< s, propagation step
        unsigned int minControlSteps{1};   ///< shortest control duration, in steps
        unsigned int maxControlSteps{10};  ///< longest control duration, in steps
        double goalBias{0.05};             ///< for planners that have one
        ompl_core::SourceLocation where;   ///< its scene file element, for messages
    };

    /** The goal: the robot centre within a disc. */
    struct GoalDisc
    {
        Eigen::Vector2d centre{Eigen::Vector2d::Zero()};  ///< world x, y, m
        double radius{0.0};                               ///< m
        ompl_core::SourceLocation where;                  ///< its scene file element, for messages
    };

    /** A physics-based pushing problem as plain data: a sphere robot driven by a planar force, rigid
        bodies classified by the manipulation knowledge (fixed, freely manipulatable,
        constraint-oriented), the floor, materials, contact and propagation parameters, the planning
        limits and the goal region. PhysicsSceneLoader reads one from a scene file; code may also
        fill one directly. Units: metres, kilograms, seconds, newtons, radians; positions and poses
        are in the world frame, z up, the floor at z = 0. */
    struct PhysicsScene
    {
        std::string name;                 ///< scene name, for messages and results
        std::string file;                 ///< scene file it came from; empty for scenes built in code
        PhysicsRobot robot;               ///< the robot
        std::vector<PhysicsBody> bodies;  ///< every other body, in scene order
        Eigen::Vector2d floorSize{
            Eigen::Vector2d::Zero()};  ///< floor extent (centred at the origin), drawing only
        Materials materials;           ///< friction coefficients
        ContactParameters contact;     ///< ODE's integration and contact parameters
        PlanningLimits limits;         ///< regions, speeds, force and control durations
        GoalDisc goal;                 ///< where the robot must get to
        double timeLimit{60.0};        ///< default planning time, s

        /** Index of the body with this name. @throws ompl::Exception when there is none. */
        std::size_t bodyIndex(const std::string &name) const;

        /** Indices of the bodies that move (free and constrained), in scene order. */
        std::vector<std::size_t> movableBodies() const;
    };

    /** How the objects that outlive a call hold a scene: shared, never a reference that can dangle.
        The scene is immutable once shared. */
    using PhysicsScenePtr = std::shared_ptr<const PhysicsScene>;
}  // namespace ompl_phys
