#pragma once

#include "ompl_core/io/SourceLocation.h"
#include "ompl_core/run/ParameterSetting.h"
#include "ompl_mm/scene/TriangleMesh.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A collision shape in URDF's vocabulary, centred at its frame (cylinders along z). Only the
        fields of its kind are used. */
    struct Shape
    {
        /** Which solid the shape is. */
        enum class Kind
        {
            Box,       ///< a box of edge lengths boxSize
            Cylinder,  ///< a cylinder of radius and length, its axis along z
            Sphere,    ///< a sphere of radius
            Mesh       ///< the triangles of mesh (robot links from URDF meshes)
        };
        Kind kind{Kind::Box};                              ///< which solid, and so which fields count
        Eigen::Vector3d boxSize{Eigen::Vector3d::Zero()};  ///< box edge lengths, metres
        double radius{0.0};                                ///< cylinder or sphere radius, metres
        double length{0.0};                                ///< cylinder length along z, metres
        std::shared_ptr<const TriangleMesh> mesh;          ///< the mesh, shared between its users

        /** Height of the shape along z (box z size, cylinder length, sphere diameter, the mesh's z
            extent), metres.
            @throws ompl::Exception when kind holds no Kind value (an out-of-range cast). */
        double height() const;
        /** Radius of the smallest vertical cylinder about the shape's axis that holds it whatever
            its yaw (box: half its horizontal diagonal), metres. @throws as height(). */
        double footprintRadius() const;
        /** Radius of the smallest sphere about the shape's centre that holds it, metres.
            @throws as height(). */
        double boundingRadius() const;
        /** True when turning the shape about its z axis leaves it the same (cylinders, spheres):
            such an object's yaw is nothing a grasp holds, so carrying it keeps its yaw. */
        bool turnsFreely() const { return kind == Kind::Cylinder || kind == Kind::Sphere; }
    };

    /** A fixed body of the workspace. */
    struct Obstacle
    {
        std::string name;                                       ///< unique among obstacles and objects
        Shape shape;                                            ///< its collision shape
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< shape centre in the world
        ompl_core::SourceLocation where;                        ///< where the scene defines it, for messages
    };

    /** A horizontal rectangle on which objects may rest, optionally the top of an obstacle. */
    struct SupportSurface
    {
        std::string name;                              ///< the surface's name, for messages
        Eigen::Vector2d min{Eigen::Vector2d::Zero()};  ///< lower x, y corner, metres
        Eigen::Vector2d max{Eigen::Vector2d::Zero()};  ///< upper x, y corner, metres
        double height{0.0};                            ///< world z of the surface, metres
        std::string obstacle;  ///< obstacle whose top this is (resting objects may touch it); may be empty
        ompl_core::SourceLocation where;  ///< where the scene defines it, for messages

        /** An object rests on the surface when its base differs from the surface's height by less
            than this, metres (the tolerance of the original MOPL implementation), and lies less than
            this outside its rectangle (so an object on an edge may be lifted straight up). */
        static constexpr double REST_TOLERANCE = 1e-4;

        /** True when the world point (x, y), metres, lies in the rectangle, edges included. */
        bool contains(double x, double y) const;

        /** True when an object whose base centre is at `base` (world frame) rests on this surface. */
        bool supports(const Eigen::Vector3d &base) const;

        /** Positive where the surface supports an object whose base is at `base` (world frame), and
            then no more than how far the base may move before it does not; not positive elsewhere.
            It changes by no more than the base moves. */
        double restMargin(const Eigen::Vector3d &base) const;
    };

    /** A box in which objects may be sampled "in the air" (held by the robot). */
    struct SamplingRegion
    {
        std::string name;                 ///< the region's name, for messages
        Eigen::AlignedBox3d box;          ///< the region in the world frame, metres
        ompl_core::SourceLocation where;  ///< where the scene defines it, for messages
    };

    /** Pose of an upright object: the centre of its base and the rotation about the vertical. */
    struct ObjectPose
    {
        Eigen::Vector3d position{Eigen::Vector3d::Zero()};  ///< base centre in the world, metres
        double yaw{0.0};                                    ///< rotation about world z, radians

        /** The object's frame in the world: at the base centre, turned by yaw about world z. */
        Eigen::Isometry3d frame() const
        {
            Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
            frame.translate(position).rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
            return frame;
        }
    };

    /** A movable rigid object; its frame is at the centre of its base, z up. Its mass and friction
        matter only where plans are simulated (planning treats objects as kinematic). */
    struct MovableObject
    {
        /** Mass when the scene gives none, kg. */
        static constexpr double DEFAULT_MASS = 1.0;
        /** Largest mass a scene may give, kg. */
        static constexpr double MAX_MASS = 1000.0;
        /** Coulomb friction coefficient when the scene gives none (wood or plastic on wood). */
        static constexpr double DEFAULT_FRICTION = 0.5;
        /** Largest friction coefficient a scene may give. */
        static constexpr double MAX_FRICTION = 5.0;

        std::string name;  ///< unique among obstacles and objects
        Shape shape;       ///< collision shape; its centre lies half its height above the base centre
        ObjectPose start;  ///< pose at the start of the problem
        double mass{DEFAULT_MASS};          ///< kg, in (0, MAX_MASS]
        double friction{DEFAULT_FRICTION};  ///< friction coefficient against anything, in [0, MAX_FRICTION]
        ompl_core::SourceLocation where;    ///< where the scene defines it, for messages
    };

    /** Two robot links never checked against each other (they touch by design). */
    struct AllowedCollision
    {
        std::string link1;                ///< a link of the robot
        std::string link2;                ///< another link of the robot
        ompl_core::SourceLocation where;  ///< where the scene allows it, for messages
    };

    /** A named frame fixed to a robot link, for inverse kinematics (a grasp frame, a push frame). */
    struct ToolFrame
    {
        std::string name;                                       ///< unique among the robot's tool frames
        std::string link;                                       ///< the link it is fixed to
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< the frame in the link's frame
        ompl_core::SourceLocation where;                        ///< where the scene declares it, for messages
    };

    /** A moving joint the scene holds still (e.g. a gripper kept open): it is no planning
        dimension, and start and goal leave it out. */
    struct FixedJointValue
    {
        std::string joint;                ///< the URDF joint's name (a moving joint, no mimic joint)
        double value{0.0};                ///< its value, metres or radians, within its limits
        ompl_core::SourceLocation where;  ///< where the scene fixes it, for messages
    };

    /** What the collision checks take for the robot links' meshes. */
    enum class MeshCollision
    {
        Exact,      ///< the triangles, as an FCL bounding-volume hierarchy (OBBRSS)
        ConvexHull  ///< the mesh's convex hull, as an FCL convex polytope: cheaper queries, conservative
    };

    /** The robot: a URDF model placed in the world. */
    struct RobotSpec
    {
        std::string urdfFile;                                       ///< absolute path of the URDF file
        Eigen::Isometry3d basePose{Eigen::Isometry3d::Identity()};  ///< URDF root frame in the world
        std::string toolLink;                                       ///< link whose origin is the tool point
        /** The tool frame in the tool link's frame: the tool point at its origin, its z the approach
            axis, its x the axis between the fingers (see docs/scene-format.md, "The tool frame"). */
        Eigen::Isometry3d toolOffset{Eigen::Isometry3d::Identity()};
        std::vector<AllowedCollision> allowedCollisions;  ///< link pairs never checked
        std::vector<ToolFrame> tools;                     ///< named frames for inverse kinematics
        std::vector<FixedJointValue> fixedJoints;         ///< joints held still, in file order
        std::string srdfFile;  ///< absolute path of the robot's SRDF file (MoveIt's format); empty: none
        std::string
            group;  ///< the SRDF's planning group: its joints are planned, the others held; empty: all
        /** Links besides the tool link's subtree that may touch a held object (the SRDF's end
            effector links). */
        std::vector<std::string> gripperLinks;
        MeshCollision meshCollision{MeshCollision::Exact};  ///< how link meshes collide
        ompl_core::SourceLocation where;  ///< where the scene defines the robot, for messages
    };

    /** One coordinate of a goal: a target value, or "don't care" when empty. */
    using GoalCoordinate = std::optional<double>;

    /** Goal of one object: position and yaw, each coordinate optional, with tolerances. */
    struct ObjectGoal
    {
        std::string object;                      ///< name of the object
        std::array<GoalCoordinate, 3> position;  ///< x, y, z of the base centre in the world, metres
        GoalCoordinate yaw;                      ///< rotation about world z, radians
        double positionTolerance{0.01};          ///< metres, per coordinate
        double yawTolerance{0.05};               ///< radians
        ompl_core::SourceLocation where;         ///< where the scene defines the goal, for messages
    };

    /** Goal of the robot: each joint optional, with one tolerance. */
    struct RobotGoal
    {
        std::vector<GoalCoordinate> joints;  ///< one entry per active joint; empty means "don't care"
        std::string state;       ///< a group state of the robot's SRDF giving the joints instead; empty: none
        double tolerance{0.01};  ///< per joint, joint units (metres or radians)
        ompl_core::SourceLocation where;  ///< where the scene defines the goal, for messages
    };

    /** A primitive the planner may use, with its parameters as written in the scene. */
    struct PrimitiveSpec
    {
        std::string type;                           ///< e.g. "transit", "push_mobile"
        std::map<std::string, std::string> params;  ///< attribute name -> value text
        ompl_core::SourceLocation where;            ///< where the scene lists it, for messages
    };

    /** Most movable objects a scene may hold: the metric keeps sets of objects as the bits of a
        64-bit word. */
    constexpr unsigned int MAX_OBJECTS = 64;

    /** A multi-modal manipulation problem as plain data: the robot, the fixed world, the movable
        objects with the surfaces they may rest on, the start, the goal and the primitives. A Scene
        is what loadScene() reads from a scene file; code may also fill one directly. Positions are
        in the world frame, in metres. */
    struct Scene
    {
        std::string name;  ///< shown in results and pictures; the loader's default is the file's stem
        std::string file;  ///< the scene file, empty for scenes built in code
        RobotSpec robot;   ///< the robot and its placement
        std::vector<Obstacle> obstacles;              ///< the fixed world
        std::vector<SupportSurface> surfaces;         ///< where objects may rest
        std::vector<SamplingRegion> samplingRegions;  ///< where held objects may be
        std::vector<MovableObject> objects;  ///< in state space order: object i is object i of the state
        std::vector<double> robotStart;      ///< one value per active joint
        std::string
            robotStartState;  ///< a group state of the robot's SRDF giving robotStart instead; empty: none
        ompl_core::SourceLocation robotStartWhere;  ///< where the scene gives the robot's start, for messages
        RobotGoal robotGoal;                        ///< the robot's part of the goal
        std::vector<ObjectGoal> objectGoals;        ///< goals of the objects that have one
        std::vector<PrimitiveSpec> primitives;      ///< the primitives the planner may use
        std::string planner{"mopl"};                ///< name in ManipulationSetup::plannerRegistry()
        std::vector<ompl_core::ParameterSetting> plannerParams;  ///< applied to the planner in order
        double timeLimit{60.0};                                  ///< default planning time, seconds

        /** Index of the object called name, or -1. */
        int objectIndex(const std::string &name) const;

        /** Gives every push primitive (type push_…) the `model` "kinematic" or "physics", as if
            each push element said so (physics needs ompl_mmphys::physicsPrimitiveFactory()).
            @throws ompl_core::InputError for another model. */
        void setPushModel(const std::string &model);

        /** Index of the first surface that supports an object whose base centre is at `base` (world
            frame), or -1 when none does (the object is held). */
        int restingSurface(const Eigen::Vector3d &base) const;
        /** Positive where restingSurface(base) is a surface that `counts` (given its index), and
            then no more than how far the base may move before it is not; not positive elsewhere.
            It changes by no more than the base moves, so a motion check can bound where an object
            rests. */
        double restMargin(const Eigen::Vector3d &base, const std::function<bool(int)> &counts) const;
    };
}  // namespace ompl_mm
