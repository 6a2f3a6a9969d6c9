#pragma once

#include "ompl_mm/robot/RobotModel.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace ompl_mm
{
    /** The joints from a robot's root to a tool frame on one of its links, with the fixed transforms
        between them folded together: forward kinematics of the tool and its geometric Jacobian in
        one pass, without allocating. Works on the whole robot's joint vector; the chain's moving
        joints are variables() of it. Immutable, so one chain may serve several threads. */
    class KinematicChain
    {
    public:
        /** The chain of robot from its root to link tip, whose tool frame is tool in the tip link's
            frame. @throws ompl::Exception when tip is not a link's index or the chain passes through a
            mimic joint. */
        KinematicChain(const RobotModel &robot, int tip,
                       const Eigen::Isometry3d &tool = Eigen::Isometry3d::Identity());

        /** Moving joints on the chain. */
        unsigned int size() const { return static_cast<unsigned int>(joints_.size()); }
        /** Index in the robot's joint vector of the chain's moving joint i (root first). */
        unsigned int variable(unsigned int i) const { return joints_[i].variable; }
        /** Lower limit of the chain's moving joint i, metres or radians. */
        double lower(unsigned int i) const { return joints_[i].lower; }
        /** Upper limit of the chain's moving joint i, metres or radians. */
        double upper(unsigned int i) const { return joints_[i].upper; }
        /** The fixed transform from the chain's moving joint i-1 (or the root, for i = 0) to joint i's
            frame. */
        const Eigen::Isometry3d &before(unsigned int i) const { return joints_[i].before; }
        /** The unit axis of the chain's moving joint i, in its frame. */
        const Eigen::Vector3d &axis(unsigned int i) const { return joints_[i].axis; }
        /** True when the chain's moving joint i slides instead of turning. */
        bool prismatic(unsigned int i) const { return joints_[i].prismatic; }
        /** The fixed transform from the last moving joint's frame (after its motion) to the tool. */
        const Eigen::Isometry3d &after() const { return after_; }
        /** True when the chain's moving joint i turns without limits (its values wrap at +-pi). */
        bool continuous(unsigned int i) const { return joints_[i].continuous; }

        /** The tool frame in the world for the robot's joint values q (size robot dof), the robot's
            root at base. */
        Eigen::Isometry3d toolPose(const double *q, const Eigen::Isometry3d &base) const;

        /** The tool frame, and in jacobian (6 x size()) the geometric Jacobian of the tool point:
            rows 0-2 its linear velocity, rows 3-5 the tool's angular velocity, world frame, per unit
            speed of each of the chain's joints. */
        Eigen::Isometry3d toolPoseAndJacobian(
            const double *q, const Eigen::Isometry3d &base,
            Eigen::Ref<Eigen::Matrix<double, 6, Eigen::Dynamic>> jacobian) const;

    private:
        /** A moving joint and the fixed transform from the previous one to its frame. */
        struct ChainJoint
        {
            Eigen::Isometry3d
                before;              ///< from the previous moving joint's frame (or the root) to this joint's
            Eigen::Vector3d axis;    ///< unit axis in this joint's frame
            bool prismatic;          ///< slides instead of turning
            bool continuous;         ///< turns without limits
            unsigned int variable;   ///< index in the robot's joint vector
            double lower, upper;     ///< limits
            int alignedAxis{-1};     ///< 0, 1, 2 when axis is +-x, +-y, +-z; -1 for any other axis
            bool turnsBefore{true};  ///< before has a rotation (most URDF joint origins have none)
        };

        /** frame * joint.before, the rotation product left out when there is none. */
        static void advance(Eigen::Isometry3d &frame, const ChainJoint &joint);

        /** Moves frame (which ends at joint's frame) by the joint's motion for value q: a turn
            about an axis along x, y or z changes two columns of the rotation only. */
        static void move(Eigen::Isometry3d &frame, const ChainJoint &joint, double q);

        std::vector<ChainJoint> joints_;
        Eigen::Isometry3d after_{Eigen::Isometry3d::Identity()};  ///< from the last moving joint to the tool
    };
}  // namespace ompl_mm
