/* A robot read from a URDF file: a tree of links joined by fixed, prismatic, revolute or
   continuous joints, with forward kinematics for every link frame and the links' collision
   shapes. Serial arms, humanoid torsos and mobile bases (two prismatic joints) are all trees. */
#pragma once

#include "ompl_mm/scene/Scene.h"

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A collision shape attached to a link. */
    struct LinkShape
    {
        Shape shape;
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< shape centre in the link frame
    };

    /** One link of the tree. */
    struct Link
    {
        std::string name;
        int parent{-1};  ///< index of the parent link, -1 for the root
        int joint{-1};   ///< index into RobotModel::joints() of the joint from the parent, -1 for the root
        std::vector<LinkShape> shapes;
    };

    /** One joint of the tree; moving joints have a variable index. */
    struct Joint
    {
        enum class Type
        {
            Fixed,
            Prismatic,
            Revolute,
            Continuous
        };
        std::string name;
        Type type{Type::Fixed};
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< child frame in the parent frame at zero
        Eigen::Vector3d axis{Eigen::Vector3d::UnitX()};           ///< unit axis in the joint frame
        double lower{0.0};                                        ///< lower limit, metres or radians
        double upper{0.0};                                        ///< upper limit, metres or radians
        int variable{-1};  ///< index in the joint vector, -1 for fixed joints
    };

    /** Kinematic tree of a robot. Copyable value type; immutable after loading.
        Links are stored parents first, so forward kinematics is one pass. */
    class RobotModel
    {
    public:
        /** Reads a URDF file.
            @throws ompl::Exception naming the file when it cannot be read or parsed, when a link has
            a mesh or another unsupported geometry, or when a moving joint has no limits. */
        static RobotModel fromUrdfFile(const std::string &path);

        /** Reads URDF text; sourceName names it in messages. */
        static RobotModel fromUrdfString(const std::string &urdf, const std::string &sourceName);

        const std::string &name() const { return name_; }
        const std::vector<Link> &links() const { return links_; }
        const std::vector<Joint> &joints() const { return joints_; }

        /** Number of moving joints (the dimension of the robot's configuration space). */
        unsigned int dof() const { return dof_; }

        /** The moving joint with variable index i. */
        const Joint &variableJoint(unsigned int i) const { return joints_[variableJoints_[i]]; }

        /** True when every moving joint is prismatic (false for a robot without moving joints). */
        bool allJointsPrismatic() const;

        /** Index of the link called name. @throws ompl::Exception when there is none. */
        int linkIndex(const std::string &name) const;

        /** True when link `descendant` is `ancestor` or lies below it in the tree. */
        bool isInSubtree(int descendant, int ancestor) const;

        /** World frames of all links for joint values q (size dof()), given the base pose.
            @pre frames has links().size() entries. */
        void forwardKinematics(const double *q, const Eigen::Isometry3d &base,
                               std::vector<Eigen::Isometry3d> &frames) const;

        /** World frame of one link (walks only the path to the root). */
        Eigen::Isometry3d linkFrame(const double *q, const Eigen::Isometry3d &base, int link) const;

    private:
        std::string name_;
        std::vector<Link> links_;
        std::vector<Joint> joints_;
        std::vector<int> variableJoints_;
        unsigned int dof_{0};
    };
}  // namespace ompl_mm
