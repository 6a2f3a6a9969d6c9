/* A multi-modal manipulation problem as plain data: the robot, the fixed world, the movable
   objects with the surfaces they may rest on, the start, the goal and the primitives. A Scene is
   what SceneLoader reads from a scene file; code may also fill one directly. */
#pragma once

#include "ompl_core/io/SourceLocation.h"
#include "ompl_core/run/ParameterSetting.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A collision shape in URDF's vocabulary, centred at its frame (cylinders along z). */
    struct Shape
    {
        enum class Kind
        {
            Box,
            Cylinder,
            Sphere
        };
        Kind kind{Kind::Box};
        Eigen::Vector3d boxSize{Eigen::Vector3d::Zero()};  ///< box edge lengths, metres
        double radius{0.0};                                ///< cylinder or sphere radius, metres
        double length{0.0};                                ///< cylinder length along z, metres

        /** Height of the shape along z (box z size, cylinder length, sphere diameter), metres. */
        double height() const;
    };

    /** A fixed body of the workspace. */
    struct Obstacle
    {
        std::string name;
        Shape shape;
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< shape centre in the world
        ompl_core::SourceLocation where;
    };

    /** A horizontal rectangle on which objects may rest, optionally the top of an obstacle. */
    struct SupportSurface
    {
        std::string name;
        Eigen::Vector2d min{Eigen::Vector2d::Zero()};  ///< lower x, y corner, metres
        Eigen::Vector2d max{Eigen::Vector2d::Zero()};  ///< upper x, y corner, metres
        double height{0.0};                            ///< world z of the surface, metres
        std::string obstacle;  ///< obstacle whose top this is (resting objects may touch it); may be empty
        ompl_core::SourceLocation where;

        /** An object rests on the surface when its base height differs from the surface's by less
            than this, metres (the tolerance of the original MOPL implementation). */
        static constexpr double REST_TOLERANCE = 1e-4;

        bool contains(double x, double y) const
        {
            return x >= min.x() && x <= max.x() && y >= min.y() && y <= max.y();
        }

        /** True when an object whose base centre is at `base` rests on this surface. */
        bool supports(const Eigen::Vector3d &base) const
        {
            return std::abs(base.z() - height) < REST_TOLERANCE && contains(base.x(), base.y());
        }
    };

    /** A box in which objects may be sampled "in the air" (held by the robot). */
    struct SamplingRegion
    {
        std::string name;
        Eigen::AlignedBox3d box;
        ompl_core::SourceLocation where;
    };

    /** Pose of an upright object: the centre of its base and the rotation about the vertical. */
    struct ObjectPose
    {
        Eigen::Vector3d position{Eigen::Vector3d::Zero()};  ///< base centre, metres
        double yaw{0.0};                                    ///< rotation about world z, radians
    };

    /** A movable rigid object; its frame is at the centre of its base, z up. */
    struct MovableObject
    {
        std::string name;
        Shape shape;
        ObjectPose start;
        ompl_core::SourceLocation where;
    };

    /** The robot: a URDF model placed in the world. */
    struct RobotSpec
    {
        std::string urdfFile;                                       ///< absolute path of the URDF file
        Eigen::Isometry3d basePose{Eigen::Isometry3d::Identity()};  ///< URDF root frame in the world
        std::string toolLink;                                       ///< link whose origin is the tool point
        Eigen::Vector3d toolOffset{Eigen::Vector3d::Zero()};        ///< tool point in the tool link frame
        std::vector<std::pair<std::string, std::string>> allowedCollisions;  ///< link pairs never checked
        ompl_core::SourceLocation where;
    };

    /** One coordinate of a goal: a target value, or "don't care" when empty. */
    using GoalCoordinate = std::optional<double>;

    /** Goal of one object: position and yaw, each coordinate optional, with tolerances. */
    struct ObjectGoal
    {
        std::string object;                      ///< name of the object
        std::array<GoalCoordinate, 3> position;  ///< x, y, z of the base centre, metres
        GoalCoordinate yaw;                      ///< radians
        double positionTolerance{0.01};          ///< metres, per coordinate
        double yawTolerance{0.05};               ///< radians
        ompl_core::SourceLocation where;
    };

    /** Goal of the robot: each joint optional, with one tolerance. */
    struct RobotGoal
    {
        std::vector<GoalCoordinate> joints;  ///< one entry per active joint; empty means "don't care"
        double tolerance{0.01};              ///< per joint, joint units (metres or radians)
        ompl_core::SourceLocation where;
    };

    /** A primitive the planner may use, with its parameters as written in the scene. */
    struct PrimitiveSpec
    {
        std::string type;                           ///< e.g. "transit", "push_mobile"
        std::map<std::string, std::string> params;  ///< attribute name -> value text
        ompl_core::SourceLocation where;
    };

    /** The whole problem. */
    struct Scene
    {
        std::string name;
        std::string file;  ///< the scene file, empty for scenes built in code
        RobotSpec robot;
        std::vector<Obstacle> obstacles;
        std::vector<SupportSurface> surfaces;
        std::vector<SamplingRegion> samplingRegions;
        std::vector<MovableObject> objects;
        std::vector<double> robotStart;  ///< one value per active joint
        ompl_core::SourceLocation robotStartWhere;
        RobotGoal robotGoal;
        std::vector<ObjectGoal> objectGoals;
        std::vector<PrimitiveSpec> primitives;
        std::string planner{"mopl"};
        std::vector<ompl_core::ParameterSetting> plannerParams;  ///< applied to the planner in order
        double timeLimit{60.0};                                  ///< default planning time, seconds

        /** Index of the object called name, or -1. */
        int objectIndex(const std::string &name) const;

        /** Index of the first surface that supports an object whose base centre is at `base`, or -1
            when none does (the object is held). */
        int restingSurface(const Eigen::Vector3d &base) const;
    };
}  // namespace ompl_mm
