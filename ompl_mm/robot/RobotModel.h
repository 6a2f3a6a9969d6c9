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
        Shape shape;                                              ///< the shape, centred at origin
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< shape centre in the link frame
    };

    /** One link of the tree. */
    struct Link
    {
        std::string name;  ///< the URDF link name
        int parent{-1};    ///< index of the parent link, -1 for the root
        int joint{-1};     ///< index into RobotModel::joints() of the joint from the parent, -1 for the root
        std::vector<LinkShape> shapes;  ///< collision shapes of the link (none for a link without any)
    };

    /** One joint of the tree; moving joints have a variable index. */
    struct Joint
    {
        /** The URDF joint types the model supports (floating and planar joints are rejected). */
        enum class Type
        {
            Fixed,      ///< does not move
            Prismatic,  ///< slides along its axis, metres
            Revolute,   ///< turns about its axis within limits, radians
            Continuous  ///< turns about its axis without URDF limits, radians
        };
        std::string name;                                         ///< the URDF joint name
        Type type{Type::Fixed};                                   ///< how it moves
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< child frame in the parent frame at zero
        Eigen::Vector3d axis{Eigen::Vector3d::UnitX()};           ///< unit axis in the joint frame
        double lower{0.0};  ///< lower limit, metres or radians (-pi for continuous joints)
        double upper{0.0};  ///< upper limit, metres or radians (pi for continuous joints)
        /** The URDF's velocity limit, metres or radians per second; 0 when it gives none (a
            continuous joint without a limit element, or velocity="0"). */
        double velocity{0.0};
        int variable{
            -1};  ///< index in the joint vector (for a mimic joint, its leader's), -1 for fixed joints
        /** The joint this one follows (URDF `<mimic>`): its index in RobotModel::joints(), -1 for a
            joint of its own. A mimic joint's value is multiplier * leader + offset; it adds no
            variable. */
        int mimics{-1};
        double multiplier{1.0};  ///< a mimic joint's factor on its leader's value; 1 otherwise
        double offset{0.0};      ///< a mimic joint's offset, metres or radians; 0 otherwise

        /** The joint's value for the joint vector q (its variable's, or its leader's scaled and
            offset). @pre variable >= 0. */
        double value(const double *q) const { return multiplier * q[variable] + offset; }
    };

    /** A robot read from a URDF file: a tree of links joined by fixed, prismatic, revolute or
        continuous joints, with forward kinematics for every link frame and the links' collision
        shapes. A joint with a URDF `<mimic>` follows its leader (a mimic of a mimic follows the
        first leader) and adds no dimension to the configuration space. Serial arms, humanoid torsos and
       mobile bases (two prismatic joints) are all trees. Copyable value type; immutable after loading. Links
       are stored parents first (the root is link 0), so forward kinematics is one pass; moving joints are
       numbered depth first, in file order within a branch. */
    class RobotModel
    {
    public:
        /** Reads a URDF file.
            @throws ompl_core::InputError (an ompl::Exception) naming the file, and the line where
            known, when it cannot be read or parsed, when a link has a mesh or a shape of non-positive
            size, when a joint is floating or planar or has a zero axis, or when a prismatic or
            revolute joint has no limits or a lower limit not below its upper one. */
        static RobotModel fromUrdfFile(const std::string &path);

        /** Reads URDF text as fromUrdfFile() does; sourceName names it in messages.
            @throws ompl_core::InputError as fromUrdfFile(). */
        static RobotModel fromUrdfString(const std::string &urdf, const std::string &sourceName);

        /** The same robot with some moving joints held still: each becomes a fixed joint at its
            value, and so do the mimic joints that follow it; the other variables keep their order.
            @throws ompl_core::InputError (without a location: the caller knows where the values
            come from) naming the joint when it is no moving joint of the robot (the message lists
            them), when it is a mimic joint (its leader is named), or when the value lies outside
            its limits. */
        RobotModel withJointsFixed(const std::vector<std::pair<std::string, double>> &values) const;

        /** The robot's name from the URDF. */
        const std::string &name() const { return name_; }
        /** All links, parents before children; link 0 is the root. */
        const std::vector<Link> &links() const { return links_; }
        /** All joints, fixed ones included; Link::joint indexes into it. */
        const std::vector<Joint> &joints() const { return joints_; }

        /** Number of moving joints (the dimension of the robot's configuration space). */
        unsigned int dof() const { return dof_; }

        /** The moving joint with variable index i (never a mimic joint). @pre i < dof(). */
        const Joint &variableJoint(unsigned int i) const { return joints_[variableJoints_[i]]; }
        /** The names of the moving joints in variable order, comma-separated, for messages. */
        std::string variableNames() const;

        /** True when every moving joint is prismatic (false for a robot without moving joints). */
        bool allJointsPrismatic() const;
        /** True when moving joint i belongs to a mobile base: it is prismatic and no turning joint
            lies between it and the root, so it translates everything below it along a fixed world
            axis. @pre i < dof(). */
        bool isBaseJoint(unsigned int i) const;

        /** Index of the link called name, or -1 when there is none. */
        int findLink(const std::string &name) const;
        /** Index of the link called name.
            @throws ompl_core::InputError (an ompl::Exception) when there is none. */
        int linkIndex(const std::string &name) const;

        /** True when link `descendant` is `ancestor` or lies below it in the tree.
            @throws ompl::Exception when either index is not a link's. */
        bool isInSubtree(int descendant, int ancestor) const;

        /** World frames of all links for joint values q (size dof()), given the base pose (the
            root link's frame in the world); frames is resized to links().size(). */
        void forwardKinematics(const double *q, const Eigen::Isometry3d &base,
                               std::vector<Eigen::Isometry3d> &frames) const;

        /** World frame of one link for joint values q (size dof()), given the base pose; walks only
            the path to the root. @throws ompl::Exception when link is not a link's index. */
        Eigen::Isometry3d linkFrame(const double *q, const Eigen::Isometry3d &base, int link) const;

    private:
        /** Numbers the moving joints that are no mimic joints in link order (depth first) and
            gives each mimic joint its leader's variable. */
        void numberVariables();

        std::string name_;
        std::vector<Link> links_;
        std::vector<Joint> joints_;
        std::vector<int> variableJoints_;
        unsigned int dof_{0};
    };
}  // namespace ompl_mm
